#pragma once
// Frames per second against resolution, one line per input x gradient x kernel (solid)
// beside the seed paper's figures (dashed, same colour), as the seed's figures drew them.
#include <string>
#include <vector>

#include "bench_run.h"

namespace voxray::cli {

// Writes a PNG (or any format voxray's image writer knows by extension). Throws Error.
void writeBenchPlot(const std::string& path, const std::vector<BenchRow>& rows);

}  // namespace voxray::cli
