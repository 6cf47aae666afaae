// The feature switches of a kernel variant. A specialised kernel gets each one as a -D
// literal, so `if (MODE == 0)` and friends fold away at compile time and only what the
// frame uses is compiled. -D UBER=1 maps them to runtime fields of the frame parameters
// instead: one kernel for every frame, kept to measure what specialisation buys.
// STORAGE_IMAGE, SLABS, COUNT_SAMPLES and HIT_OUTPUT stay compile-time: they change
// arguments and stores.
// Code that uses a switch must have the frame parameters in scope as `P`.
#ifndef VOXRAY_VARIANT_CL
#define VOXRAY_VARIANT_CL

#include "params.cl"

#if UBER
#define MODE (P->modes.x)
#define SHADING (P->modes.y)
#define GRADIENT (P->modes.z)
#define INTERP (P->modes.w)
#define ORTHO (P->modes2.x)
#define REFINE_STEPS (P->modes2.y)
#define OPACITY_CORRECTION (P->modes2.z)
#define JITTER (P->modes2.w)
#define ESS (P->cells.w)
#else
// Switches a variant leaves out default to off; the host passes all that matter.
#ifndef MODE
#define MODE 0
#endif
#ifndef SHADING
#define SHADING 0
#endif
#ifndef GRADIENT
#define GRADIENT 0
#endif
#ifndef INTERP
#define INTERP 1
#endif
#ifndef ORTHO
#define ORTHO 0
#endif
#ifndef REFINE_STEPS
#define REFINE_STEPS 0
#endif
#ifndef OPACITY_CORRECTION
#define OPACITY_CORRECTION 0
#endif
#ifndef JITTER
#define JITTER 0
#endif
#ifndef ESS
#define ESS 0
#endif
#endif

#ifndef STORAGE_IMAGE
#define STORAGE_IMAGE 0
#endif
#ifndef SLABS
#define SLABS 1
#endif
#ifndef COUNT_SAMPLES
#define COUNT_SAMPLES 0
#endif
#ifndef HIT_OUTPUT
#define HIT_OUTPUT 0
#endif

#endif
