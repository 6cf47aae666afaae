#pragma once
// The point and plane flags of voxray-cli measure, shared with export-sr.
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace voxray::cli {

// "I:J:K" (voxels) or "X:Y:Z" (LPS mm), points separated by commas; exactly COUNT points.
// Throws Error (Input) naming FLAG otherwise.
std::vector<glm::dvec3> parsePoints(const std::string& text, size_t count, const char* flag);

// "i", "j" or "k": the voxel axis across an ROI's plane (0, 1, 2).
int planeAxis(const std::string& s);

}  // namespace voxray::cli
