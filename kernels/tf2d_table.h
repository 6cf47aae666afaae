// The 2D transfer function's table (issue 35, TF2D in switches.h): float4 RGBA entries, this many
// columns over stored values by this many rows over |gradient|, row-major, riding in the table
// buffer right behind the colour and opacity table (the light grid then starts this many float4s
// later). Shared by the kernels and the engine (engine/src/tf2d.cpp bakes it).
#ifndef VOXRAY_TF2D_TABLE_H
#define VOXRAY_TF2D_TABLE_H

#define VOXRAY_TF2D_VALUES 256
#define VOXRAY_TF2D_GRADIENTS 64
#define VOXRAY_TF2D_FLOAT4S (VOXRAY_TF2D_VALUES * VOXRAY_TF2D_GRADIENTS)

#endif
