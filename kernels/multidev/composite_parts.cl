// The sort-last composite on the first device (engine/src/multi_device_gpu_composite.cpp,
// issue 38): its own part's image (float RGBA, raycast_part.cl) and the other parts' images in
// half floats (raycast_part.cl with PART_HALF, read back from their devices and uploaded here),
// into RGBA8, one band of rows per launch (global offset: the band's first row).
//
// The parts are z slabs, so one order fits every pixel of the frame (multi_device.h's
// visibilityKeys): `order` packs the parts front to back, 4 bits each (0: this device's own
// part, k: other image k - 1). A part a ray does not meet holds (0, 0, 0, 0), so its place in
// the order changes nothing. As the host's compositeParts: dvr "over" front to back until the
// opacity reaches earlyTermination, then the background; iso the first part in order with a
// hit; mip the maximum over the parts whose ray met the clip box, else the background.
// MODE: 0 iso, 1 dvr, 2 mip (raycast_part.cl's). Built without -cl-fast-relaxed-math so that
// it rounds as the host's composite and the kernels' to_rgba8 (shading.cl): to nearest even.

inline float4 part_pixel(__global const float4* own, __global const half* others, uint part,
                         size_t px, size_t pixels) {
  if (part == 0) return own[px];
  return vload_half4(px + (size_t)(part - 1) * pixels, others);
}

__kernel void composite_parts(__global const float4* own, __global const half* others,
                              __global uchar4* out, int width, int height, int parts, uint order,
                              float4 background) {
  int x = get_global_id(0), y = get_global_id(1);
  if (x >= width || y >= height) return;
  size_t px = (size_t)y * width + x, pixels = (size_t)width * height;
  float3 rgb = background.xyz;
  if (MODE == 1) {
    float3 acc = (float3)(0.0f);
    float alpha = 0.0f;
    for (int k = 0; k < parts && alpha < background.w; ++k) {
      float4 c = part_pixel(own, others, (order >> (4 * k)) & 15u, px, pixels);
      acc += (1.0f - alpha) * c.xyz;
      alpha += (1.0f - alpha) * c.w;
    }
    rgb = acc + (1.0f - alpha) * background.xyz;
  } else if (MODE == 0) {
    for (int k = 0; k < parts; ++k) {
      float4 c = part_pixel(own, others, (order >> (4 * k)) & 15u, px, pixels);
      if (c.w > 0.0f) {
        rgb = c.xyz;
        break;
      }
    }
  } else {
    float grey = -1.0f;
    for (int k = 0; k < parts; ++k) {
      float4 c = part_pixel(own, others, (uint)k, px, pixels);
      if (c.w > 0.0f) grey = fmax(grey, c.x);
    }
    if (grey >= 0.0f) rgb = (float3)(grey);
  }
  out[px] = (uchar4)(convert_uchar3_sat_rte(clamp(rgb, 0.0f, 1.0f) * 255.0f), 255);
}
