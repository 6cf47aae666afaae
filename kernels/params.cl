// Frame parameters, one __constant struct per frame. The host mirror is
// engine/src/kernel_params.h: both list float4/int4 members only, in the same order,
// so the layouts agree on every device.
#ifndef VOXRAY_PARAMS_CL
#define VOXRAY_PARAMS_CL

// Edge of a macro cell of the empty-space grid, in voxels (engine/src/macro_cells.h).
#define CELL 4

typedef struct {
  float4 eye_w;  // world (LPS mm from the volume centre)
  float4 forward_w;
  float4 right_w;
  float4 up_w;
  float4 eye_v;  // the same in voxel coordinates
  float4 forward_v;
  float4 right_v;
  float4 up_v;
  float4 clip_lo;  // clip box, voxel coordinates
  float4 clip_hi;
  float4 grad_x;  // rows of the voxel-gradient -> world-gradient matrix
  float4 grad_y;
  float4 grad_z;
  float4 light_w;
  float4 light;  // ambient, diffuse, specular, shininess
  float4 background;
  float4 view;    // half height, aspect, step (mm), reference step (mm) for opacity
  float4 values;  // iso lo, iso hi (stored units), lut min, lut scale (entries per unit)
  float4 dvr;     // mip window low, 1 / mip window width, early termination, unused
  int4 dims;      // volume x, y, z, lut entries
  int4 image;     // width, height, unused, unused
  int4 cells;     // macro-cell grid x, y, z (cells of CELL^3 voxels); ESS (uber only)
  int4 modes;     // MODE, SHADING, GRADIENT, INTERP (read by uber kernels only)
  int4 modes2;    // ORTHO, REFINE_STEPS, OPACITY_CORRECTION, JITTER (uber only)
  int4 slabs;     // slices each z slab owns (SLABS > 1, slabs.cl), unused, unused, unused
} RaycastParams;

#endif
