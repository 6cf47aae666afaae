#pragma once
#include "cl_errors.h"
#include "voxray/io/error.h"

namespace voxray {

template <class F>
auto clCall(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const cl::Error& e) {
    throw deviceError(clErrorMessage(e.what(), e.err()));
  }
}

}  // namespace voxray
