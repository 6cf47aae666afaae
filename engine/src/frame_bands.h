#pragma once
// Bands of rows a frame is rendered and composited in (multi_device_gpu_composite.h).
#include <vector>

namespace voxray {

// Rows [first, first + rows) of the frame.
struct FrameBand {
  int first = 0, rows = 0;
};

// COUNT bands (0: by the height, about 256 rows each, at most 8) of a multiple of ROWSTEP
// rows each (the kernels' work-group height), the last taking the rest.
std::vector<FrameBand> frameBands(int height, int count, int rowStep);

}  // namespace voxray
