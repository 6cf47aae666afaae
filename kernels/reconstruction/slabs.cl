// Volumes split along z into SLABS slabs (engine/src/slab_plan.h) when one allocation or
// 3D image cannot hold them. The kernels then take one volume argument per slab, vol0 ..
// vol{SLABS-1}; slab s owns slices [s * D, (s + 1) * D) (D = P->slabs.x) and stores
// SLAB_APRON more on each side, clamped to the volume. A sample or gradient at p reads the
// slab owning floor(p.z), with z made relative to the slab's first stored slice and the
// slab's stored depth as dims.z. Clamping at an apron edge then equals clamping at the
// volume's edge: a stencil reaches one slice below floor(p.z) and two above, so apron edges
// that are not volume edges are never reached. The shift p.z - first is exact in float
// (first <= floor(p.z), both below 2^24), so the buffer path reads the same voxels with the
// same weights as one volume.
//   SLABS 1 (the default): one argument, `vol`; none of this is compiled.
// Code reading the volume takes VOLUME_ARG and passes VOLUME on; sampling.cl and
// gradients.cl read through RETURN_FROM_SLAB.
#ifndef VOXRAY_SLABS_CL
#define VOXRAY_SLABS_CL

#include "variant.cl"

#if SLABS == 1 && defined(VOXRAY_PART)
// One part of a multi-device frame (multidev/raycast_part.cl): `vol` holds slices [part.x,
// part.x + part.y) of the volume; z shifts by an integer as for slabs below.
#define VOLUME_ARG SLAB_TYPE vol, int2 part
#define VOLUME vol, part
#define RETURN_FROM_SLAB(FN, P, p)                                         \
  return FN(vol, (int4)((P)->dims.x, (P)->dims.y, part.y, (P)->dims.w), P, \
            (float3)((p).x, (p).y, (p).z - (float)part.x))
#elif SLABS == 1
#define VOLUME_ARG SLAB_TYPE vol
#define VOLUME vol
// Returns FN(volume, its dims, P, p): FN reads one slab, here the whole volume.
#define RETURN_FROM_SLAB(FN, P, p) return FN(vol, (P)->dims, P, p)
#else
#define SLAB_APRON 2  // engine/src/slab_plan.h: SlabPlan::kApron

#define SLAB_ARGS_2 SLAB_TYPE vol0, SLAB_TYPE vol1
#define SLAB_ARGS_3 SLAB_ARGS_2, SLAB_TYPE vol2
#define SLAB_ARGS_4 SLAB_ARGS_3, SLAB_TYPE vol3
#define SLAB_ARGS_5 SLAB_ARGS_4, SLAB_TYPE vol4
#define SLAB_ARGS_6 SLAB_ARGS_5, SLAB_TYPE vol5
#define SLAB_ARGS_7 SLAB_ARGS_6, SLAB_TYPE vol6
#define SLAB_ARGS_8 SLAB_ARGS_7, SLAB_TYPE vol7
#define SLAB_NAMES_2 vol0, vol1
#define SLAB_NAMES_3 SLAB_NAMES_2, vol2
#define SLAB_NAMES_4 SLAB_NAMES_3, vol3
#define SLAB_NAMES_5 SLAB_NAMES_4, vol4
#define SLAB_NAMES_6 SLAB_NAMES_5, vol5
#define SLAB_NAMES_7 SLAB_NAMES_6, vol6
#define SLAB_NAMES_8 SLAB_NAMES_7, vol7
#define SLAB_JOIN(a, b) a##b
#define SLAB_EXPAND(a, b) SLAB_JOIN(a, b)
#define VOLUME_ARG SLAB_EXPAND(SLAB_ARGS_, SLABS)
#define VOLUME SLAB_EXPAND(SLAB_NAMES_, SLABS)

// FN on slab volume v, with the slab's dims and point (RETURN_FROM_SLAB's locals).
#define SLAB_RETURN(FN, v) return FN(v, slab_dims_, P, slab_p_)
#if STORAGE_IMAGE
// Images cannot be held in variables: one case per slab.
#define SLAB_CASES_2(FN)   \
  default:                 \
  case 0:                  \
    SLAB_RETURN(FN, vol0); \
  case 1:                  \
    SLAB_RETURN(FN, vol1);
#define SLAB_CASES_3(FN) SLAB_CASES_2(FN) case 2 : SLAB_RETURN(FN, vol2);
#define SLAB_CASES_4(FN) SLAB_CASES_3(FN) case 3 : SLAB_RETURN(FN, vol3);
#define SLAB_CASES_5(FN) SLAB_CASES_4(FN) case 4 : SLAB_RETURN(FN, vol4);
#define SLAB_CASES_6(FN) SLAB_CASES_5(FN) case 5 : SLAB_RETURN(FN, vol5);
#define SLAB_CASES_7(FN) SLAB_CASES_6(FN) case 6 : SLAB_RETURN(FN, vol6);
#define SLAB_CASES_8(FN) SLAB_CASES_7(FN) case 7 : SLAB_RETURN(FN, vol7);
#define SLAB_CALL(FN, s) \
  switch (s) { SLAB_EXPAND(SLAB_CASES_, SLABS)(FN) }
#else
// Buffers: one copy of the reading code, on the selected pointer.
inline __global const short* slab_pointer(VOLUME_ARG, int s) {
  __global const short* slabs[SLABS] = {VOLUME};
  return slabs[s];
}
#define SLAB_CALL(FN, s) SLAB_RETURN(FN, slab_pointer(VOLUME, s))
#endif

// The slab owning slice floor(z); outside the volume, the nearest end slab. Compares, not a
// division: exact, cheap, and always a valid slab (even for NaN).
inline int slab_of(__constant RaycastParams* P, float z) {
  int zi = convert_int(clamp(floor(z), -1.0f, (float)P->dims.z));
  int s = 0;
  for (int k = 1; k < SLABS; ++k) s += zi >= k * P->slabs.x;
  return s;
}

inline int slab_first(__constant RaycastParams* P, int s) {
  return max(s * P->slabs.x - SLAB_APRON, 0);
}

// The slab's extent in voxels: the volume's x and y, its stored slices along z.
inline int4 slab_dims(__constant RaycastParams* P, int s) {
  int end = min((s + 1) * P->slabs.x + SLAB_APRON, P->dims.z);
  return (int4)(P->dims.x, P->dims.y, end - slab_first(P, s), P->dims.w);
}

inline float3 slab_point(__constant RaycastParams* P, int s, float3 p) {
  return (float3)(p.x, p.y, p.z - (float)slab_first(P, s));
}

// Returns FN(slab volume, its dims, P, p in it) for the slab owning floor(p.z).
#define RETURN_FROM_SLAB(FN, P, p)          \
  int slab_ = slab_of(P, (p).z);            \
  int4 slab_dims_ = slab_dims(P, slab_);    \
  float3 slab_p_ = slab_point(P, slab_, p); \
  SLAB_CALL(FN, slab_)
#endif

#endif
