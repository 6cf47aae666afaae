// The frame parameters, one __constant struct per frame, declared once: params.cl builds the
// kernels' RaycastParams from this list and engine/src/kernel_params.h the host's, so the two
// cannot drift. float4/int4 members only (cl_float4/cl_int4 on the host): their layout agrees
// on every device. VOXRAY_PARAM(TYPE, NAME), NAME possibly an array.
// Deliberately without a guard.
VOXRAY_PARAM(float4, eye_w)  // world (LPS mm from the volume centre)
VOXRAY_PARAM(float4, forward_w)
VOXRAY_PARAM(float4, right_w)
VOXRAY_PARAM(float4, up_w)
VOXRAY_PARAM(float4, eye_v)  // the same in voxel coordinates
VOXRAY_PARAM(float4, forward_v)
VOXRAY_PARAM(float4, right_v)
VOXRAY_PARAM(float4, up_v)
VOXRAY_PARAM(float4, clip_lo)  // clip box, voxel coordinates
VOXRAY_PARAM(float4, clip_hi)
VOXRAY_PARAM(float4, grad_x)  // rows of the voxel-gradient -> world-gradient matrix
VOXRAY_PARAM(float4, grad_y)
VOXRAY_PARAM(float4, grad_z)
VOXRAY_PARAM(float4, light_w)
VOXRAY_PARAM(float4, light)  // ambient, diffuse, specular, shininess
VOXRAY_PARAM(float4, background)
VOXRAY_PARAM(float4, view)  // half height, aspect, step (mm), reference step (mm) for opacity
// iso lo, iso hi (stored units), lut min, lut scale (entries per stored unit)
VOXRAY_PARAM(float4, values)
VOXRAY_PARAM(float4, dvr)  // mip window low, 1 / mip window width, early termination, unused
VOXRAY_PARAM(int4, dims)   // volume x, y, z, lut entries
VOXRAY_PARAM(int4, image)  // width, height, unused, unused
VOXRAY_PARAM(int4, cells)  // macro-cell grid x, y, z (cells of CELL^3 voxels), unused
VOXRAY_PARAM(int4, slabs)  // slices each z slab owns (SLABS > 1, slabs.cl), unused x 3
// Every switch's value by its slot (switch_slots.h); read through P_SWITCH.
VOXRAY_PARAM(int4, switches[VOXRAY_SWITCH_VECTORS])
// Lighting beyond Phong (LIGHTING, kernels/lighting/light_volume.cl): the light in voxel
// coordinates; rows of the voxel -> world matrix (mm lengths of voxel steps); the light grid's
// points x, y, z and its cell edge in voxels; ao radius (mm), march step (mm), 1 / cell, shadow
// offset (mm: shadowOffsetMm() of engine/include/voxray/engine/monte_carlo_reference.h).
VOXRAY_PARAM(float4, light_v)
VOXRAY_PARAM(float4, to_world_x)
VOXRAY_PARAM(float4, to_world_y)
VOXRAY_PARAM(float4, to_world_z)
VOXRAY_PARAM(int4, light_grid)
VOXRAY_PARAM(float4, light_march)
// GRADIENT_OPACITY (gradient_table.h): table entries per stored unit / mm of |gradient|, the
// last entry, unused x 2.
VOXRAY_PARAM(float4, gradient_opacity)
// TF2D (tf2d_table.h): the stored value of column 0, columns per stored unit, rows per stored
// unit / mm of |gradient|, unused.
VOXRAY_PARAM(float4, tf2d)
// PREINT (preint_table.h): the stored value of row and column 0, rows per stored unit, unused x 2.
VOXRAY_PARAM(float4, preint)
// Image-space adaptive sampling (IMAGE_PASS, adaptive/image_pass.cl): the lattice's spacing K,
// its columns and rows, unused.
VOXRAY_PARAM(int4, image_pass)
