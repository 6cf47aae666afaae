// OVERLAY (switches.h): fused dvr of a second volume (issue 36, e.g. PET on CT), and fused
// mip (overlay_mip). Each dvr sample also classifies the overlay at the same patient point: its
// voxel position from the base's by an affine map (patient space through both volumes' origin,
// spacing and LPS direction, so the grids need not match), trilinear there, clamped to its edge
// voxels inside its box and transparent outside it, then its own table. Arguments (OVERLAY_PARAMS):
//   ovol  the overlay's stored values (short, x fastest)
//   olut  its colour and opacity table (float4, as lut.cl's)
//   ocells per base macro cell (x fastest), 1 where the overlay may show (overlay_cells.h):
//         elsewhere its sample is transparent, so it is not taken (overlay_cell)
//   ogeo  [0 .. 2] rows of the map base voxel -> overlay voxel (xyz linear, w translation),
//         [3] xyz its dims, w its table's last entry, [4] x the table's first stored value,
//         y its entries per stored unit, z 1 when the table is transparent only below its
//         first visible value (overlay_mip may leave out the cells where it shows nothing),
//         w its largest opacity (0 ... 1: what overlay_mip lays over the grey)
// engine/src/overlay.cpp fills them; engine/src/reference_renderer.cpp does the same in
// double precision.
#ifndef VOXRAY_OVERLAY_CL
#define VOXRAY_OVERLAY_CL

#include "intersection/ray.cl"
#include "params.cl"

#if OVERLAY
#define OVERLAY_PARAMS                                                         \
  , __global const short *restrict ovol, __global const float4 *restrict olut, \
      __global const uchar *restrict ocells, __constant float4 *ogeo
#define OVERLAY_PASS , ovol, olut, ocells, ogeo

// Whether base voxel position p lies in a macro cell where the overlay may show: cell
// floor(p / CELL) (clamped), whose span (macro_cells.h) holds p.
inline bool overlay_cell(__global const uchar* restrict ocells, __constant RaycastParams* P,
                         float3 p) {
  int3 c = clamp(convert_int3(floor(p * (1.0f / CELL))), (int3)(0), P->cells.xyz - 1);
  return ocells[((size_t)c.z * P->cells.y + c.y) * P->cells.x + c.x] != 0;
}

// The overlay's stored value at base voxel position p (trilinear, clamped to its edge voxels);
// false outside its box, where it is transparent.
inline bool overlay_value(__global const short* restrict ovol, __constant float4* ogeo, float3 p,
                          float* value) {
  float4 p4 = (float4)(p, 1.0f);
  float3 q = (float3)(dot(ogeo[0], p4), dot(ogeo[1], p4), dot(ogeo[2], p4));
  float3 d = ogeo[3].xyz;
  if (any(q < -0.5f) || any(q > d - 0.5f)) return false;
  float3 f = floor(q);
  float3 w = q - f;
  int3 n = convert_int3(d) - 1;
  int3 a = clamp(convert_int3(f), (int3)(0), n), b = clamp(convert_int3(f) + 1, (int3)(0), n);
  size_t sy = (size_t)(n.x + 1), sz = sy * (size_t)(n.y + 1);
#define OV(x, y, z) (float)ovol[(size_t)(z)*sz + (size_t)(y)*sy + (size_t)(x)]
  float c00 = mix(OV(a.x, a.y, a.z), OV(b.x, a.y, a.z), w.x);
  float c10 = mix(OV(a.x, b.y, a.z), OV(b.x, b.y, a.z), w.x);
  float c01 = mix(OV(a.x, a.y, b.z), OV(b.x, a.y, b.z), w.x);
  float c11 = mix(OV(a.x, b.y, b.z), OV(b.x, b.y, b.z), w.x);
#undef OV
  *value = mix(mix(c00, c10, w.y), mix(c01, c11, w.y), w.z);
  return true;
}

// The overlay table's colour and opacity (per reference step) for stored value v.
inline float4 overlay_lookup(__global const float4* restrict olut, __constant float4* ogeo,
                             float v) {
  float last = ogeo[3].w;
  float x = clamp((v - ogeo[4].x) * ogeo[4].y, 0.0f, last);
  float i = floor(x);
  int k = (int)i;
  int k1 = min(k + 1, (int)last);
  return mix(olut[k], olut[k1], x - i);
}

// The overlay's colour and opacity (per reference step) at base voxel position p.
inline float4 overlay_classify(__global const short* restrict ovol,
                               __global const float4* restrict olut, __constant float4* ogeo,
                               float3 p) {
  float v;
  if (!overlay_value(ovol, ogeo, p, &v)) return (float4)(0.0f);
  return overlay_lookup(olut, ogeo, v);
}

// Fused mip: the overlay's largest value at the ray's mip sample positions, through its
// table, over the volume's mip grey as the slice views fuse it: the table's colour at that
// value with the table's largest opacity (ogeo[4].w; a window's table: its opacity at and
// above the high end, the user's) wherever the table shows the value at all, GREY elsewhere.
inline float3 overlay_mip(__global const short* restrict ovol, __global const float4* restrict olut,
                          __global const uchar* restrict ocells, __constant float4* ogeo,
                          __constant RaycastParams* P, const Ray* r, float3 grey) {
  // Only the samples in the overlay's box can see it: the ray mapped into its voxels (the same
  // t, the map being affine) through its box, a sample's margin either way for rounding.
  float4 o4 = (float4)(r->o, 1.0f), d4 = (float4)(r->d, 0.0f);
  float3 qo = (float3)(dot(ogeo[0], o4), dot(ogeo[1], o4), dot(ogeo[2], o4));
  float3 qd = (float3)(dot(ogeo[0], d4), dot(ogeo[1], d4), dot(ogeo[2], d4));
  float ta, tb;
  if (intersect_box(qo, qd, (float3)(-0.5f), ogeo[3].xyz - 0.5f, &ta, &tb) <= -2) return grey;
  int first = (int)clamp(floor((ta - r->t0) / r->step - r->j) - 1.0f, 0.0f, (float)r->n);
  int last = (int)clamp(ceil((tb - r->t0) / r->step - r->j) + 1.0f, 0.0f, (float)r->n);
  // A table transparent only below its first visible value (ogeo[4].z, e.g. a window's):
  // samples in macro cells where it shows nothing are below every visible value, so they can
  // neither be the shown maximum nor hide one; they are not taken.
  bool leap = ogeo[4].z != 0.0f;
  float vmax = -FLT_MAX, v;
  for (int i = first; i <= last; ++i) {
    float3 p = r->o + ray_sample_t(r, i) * r->d;
    if (leap && !overlay_cell(ocells, P, p)) continue;
    if (overlay_value(ovol, ogeo, p, &v)) vmax = fmax(vmax, v);
  }
  if (vmax == -FLT_MAX) return grey;
  float4 c = overlay_lookup(olut, ogeo, vmax);
  if (!(c.w > 0.0f)) return grey;
  return mix(grey, c.xyz, ogeo[4].w);
}
#else
#define OVERLAY_PARAMS
#define OVERLAY_PASS
#endif

#endif
