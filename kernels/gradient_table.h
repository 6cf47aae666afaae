// The gradient-opacity table (issue 35, GRADIENT_OPACITY in switches.h): this many float
// factors over |gradient| 0 ... its last point, riding in the table buffer right behind the
// colour and opacity table (and before the light grid, which then starts this many floats
// later). Shared by the kernels and the engine (engine/src/transfer_function.cpp bakes it).
#ifndef VOXRAY_GRADIENT_TABLE_H
#define VOXRAY_GRADIENT_TABLE_H

#define VOXRAY_GRADIENT_TABLE_ENTRIES 256
// The same in the table buffer's float4 entries.
#define VOXRAY_GRADIENT_TABLE_FLOAT4S (VOXRAY_GRADIENT_TABLE_ENTRIES / 4)

#endif
