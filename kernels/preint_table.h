// The pre-integrated classification's table (PREINT in switches.h): float4 entries, row the
// front sample's value, column the back sample's, this many each, row-major, riding in the
// table buffer right behind the colour and opacity table (the light grid then starts this
// many float4s later). Each entry holds the opacity-weighted mean colour (rgb) and the optical
// depth in log2 units (w) of a segment of the frame's step over which the value runs linearly
// from the row's to the column's (Engel, Kraus, Ertl 2001). Shared by the kernels and the
// engine (engine/src/preint_table.cpp bakes it).
#ifndef VOXRAY_PREINT_TABLE_H
#define VOXRAY_PREINT_TABLE_H

#define VOXRAY_PREINT_VALUES 256
#define VOXRAY_PREINT_FLOAT4S (VOXRAY_PREINT_VALUES * VOXRAY_PREINT_VALUES)

#endif
