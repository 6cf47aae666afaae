// Each switch of switches.h has a slot in the frame parameters (RaycastParams.switches, int4
// vectors): its index in the list. Shared by the kernels and the engine.
#ifndef VOXRAY_SWITCH_SLOTS_H
#define VOXRAY_SWITCH_SLOTS_H

enum {
#define VOXRAY_SWITCH(NAME, DEFAULT, KIND, LABELS) VOXRAY_SLOT_##NAME,
#include "switches.h"
#undef VOXRAY_SWITCH
  VOXRAY_SWITCH_COUNT
};
#define VOXRAY_SWITCH_VECTORS ((VOXRAY_SWITCH_COUNT + 3) / 4)

#endif
