// The feature switches of a kernel variant (switches.h). The host passes every one as a -D
// option (engine/src/kernel_switches.cpp): a literal in a specialised kernel, so `if (MODE ==
// 0)` and friends fold away at compile time and only what the frame uses is compiled, or
// P_SWITCH(slot) (params.cl) where it is read at run time. Code that uses a switch must have
// the frame parameters in scope as `P`.
#ifndef VOXRAY_VARIANT_CL
#define VOXRAY_VARIANT_CL

#include "params.cl"

#ifndef VOXRAY_SWITCHES_SET
#error "raycast.cl needs the -D options of engine/src/kernel_switches.cpp (switchOptions)"
#endif

#endif
