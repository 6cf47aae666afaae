// SURFACES (switches.h): the dvr march inserts the surface pass's layer (surface_layer.h,
// surface/surface_layer.cl) into its composite at the layer's depth: before the first sample
// at or beyond it, or at the ray's end. Samples the march leaps (empty space) add nothing, so
// inserting the layer at the next sample keeps the front-to-back order.
#ifndef VOXRAY_SURFACES_CL
#define VOXRAY_SURFACES_CL

#include "params.cl"
#include "surface_layer.h"

#if SURFACES
#define SURFACE_PARAMS , __global const float4* restrict surf
#define SURFACE_PASS , surf

// The layer into the composite (acc, alpha): what lies in front already there.
inline void surface_composite(float4 layer, float3* acc, float* alpha) {
  *acc += (1.0f - *alpha) * layer.xyz;
  *alpha += (1.0f - *alpha) * layer.w;
}
#else
#define SURFACE_PARAMS
#define SURFACE_PASS
#endif

#endif
