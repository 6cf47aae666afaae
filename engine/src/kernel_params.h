#pragma once
// Host mirror of kernels/params.cl: float4/int4 members only, in the same order.
#include <CL/opencl.hpp>

namespace voxray {

struct RaycastParams {
  cl_float4 eye_w, forward_w, right_w, up_w;
  cl_float4 eye_v, forward_v, right_v, up_v;
  cl_float4 clip_lo, clip_hi;
  cl_float4 grad_x, grad_y, grad_z;
  cl_float4 light_w;
  cl_float4 light;
  cl_float4 background;
  cl_float4 view;
  cl_float4 values;
  cl_float4 dvr;
  cl_int4 dims;
  cl_int4 image;
  cl_int4 cells;
  cl_int4 modes;
  cl_int4 modes2;
  cl_int4 slabs;
};
static_assert(sizeof(RaycastParams) == 25 * 16, "must match kernels/params.cl");

}  // namespace voxray
