// One part's image into an out-of-core frame's composite on the device (engine/src/
// out_of_core.cpp, issue 38 part 2): the parts come in the order the rays meet them, so each
// is composited behind what is there. The same arithmetic as the host's composite
// (multi_device_composite.cpp), without contraction into fma, so that it rounds the same.
#pragma OPENCL FP_CONTRACT OFF

// mode: 0 iso (the first slab's hit), 1 dvr ("over", stopping at early termination et),
// 2 mip (the largest value where a ray met the clip box; acc.w marks that one did).
__kernel void accumulate_part(__global const float4* colour, __global float4* acc, int mode,
                              float et, int pixels) {
  int i = get_global_id(0);
  if (i >= pixels) return;
  float4 c = colour[i];
  float4 a = acc[i];
  if (mode == 1) {
    if (a.w < et) {
      float t = 1.0f - a.w;
      a.x += t * c.x;
      a.y += t * c.y;
      a.z += t * c.z;
      a.w += t * c.w;
    }
  } else if (mode == 0) {
    if (a.w == 0.0f && c.w > 0.0f) a = c;
  } else if (c.w > 0.0f) {
    a.x = a.w > 0.0f ? fmax(a.x, c.x) : c.x;
    a.w = 1.0f;
  }
  acc[i] = a;
}
