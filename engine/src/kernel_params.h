#pragma once
// The host's frame parameters, built from the same list as the kernels' (kernels/frame_params.h).
#include <CL/opencl.hpp>

#include "switch_slots.h"

namespace voxray {

struct RaycastParams {
#define VOXRAY_PARAM(TYPE, NAME) cl_##TYPE NAME;
#include "frame_params.h"
#undef VOXRAY_PARAM
};

}  // namespace voxray
