// The surface pass of segments shown as surfaces (issue 34, kernels/surface/surface_layer.cl,
// engine/src/raycaster.cpp): shared by the kernels and the engine.
// Per surface three int4 in `geo` and one float4 in `colours`:
//   geo[3 s]     x, y, z: the field's voxel (0,0,0) in the volume; w: its first byte in `fields`
//   geo[3 s + 1] x, y, z: the field's dims; w: the first byte of its block flags in `fields`
//   geo[3 s + 2] x, y, z: the block grid's dims; w: the segment's label
//   colours[s]   the segment's colour r, g, b and its opacity
// The block flags: one byte per SURFACE_BLOCK^3 voxels of the field, 1 where a value of the
// block or of the next voxel along each axis (what trilinear reads reach) is at least 128.
// The layer: per pixel two float4, the surfaces' composite (premultiplied colour, opacity)
// and (the nearest surface's ray depth t in mm, or SURFACE_NONE, 0, 0, 0).
#ifndef VOXRAY_SURFACE_LAYER_H
#define VOXRAY_SURFACE_LAYER_H

#define SURFACE_BLOCK 8
#define SURFACE_MAX 8  // surfaces one frame draws (the segment panel's first 8 surface segments)
#define SURFACE_NONE 3.0e38f

#endif
