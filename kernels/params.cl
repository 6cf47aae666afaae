// Frame parameters, one __constant struct per frame, built from frame_params.h (the host
// builds its mirror from the same list: engine/src/kernel_params.h).
#ifndef VOXRAY_PARAMS_CL
#define VOXRAY_PARAMS_CL

#include "switch_slots.h"

// Edge of a macro cell of the empty-space grid, in voxels (engine/src/macro_cells.h).
#define CELL 4

typedef struct {
#define VOXRAY_PARAM(TYPE, NAME) TYPE NAME;
#include "frame_params.h"
#undef VOXRAY_PARAM
} RaycastParams;

// A switch read at run time from the frame parameters in scope as P (variant.cl).
#define P_SWITCH(SLOT) (((__constant const int*)P->switches)[SLOT])

#endif
