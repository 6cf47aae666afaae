#include "measure_points.h"

#include <sstream>

#include "voxray/io/error.h"

namespace voxray::cli {

std::vector<glm::dvec3> parsePoints(const std::string& text, size_t count, const char* flag) {
  std::vector<glm::dvec3> out;
  std::stringstream points(text);
  std::string p;
  const std::string usage = std::string(flag) + " '" + text + "': give " + std::to_string(count) +
                            " points as I:J:K (voxels, or X:Y:Z mm with --mm) separated by commas";
  while (std::getline(points, p, ',')) {
    glm::dvec3 v;
    char c1 = 0, c2 = 0, extra = 0;
    std::istringstream in(p);
    if (!(in >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ':' || c2 != ':' || (in >> extra) ||
        !glm::all(glm::lessThan(glm::abs(v), glm::dvec3(1e9))))
      throw inputError(usage);
    out.push_back(v);
  }
  if (out.size() != count) throw inputError(usage);
  return out;
}

int planeAxis(const std::string& s) {
  if (s == "i") return 0;
  if (s == "j") return 1;
  if (s == "k") return 2;
  throw inputError("--plane '" + s + "': give i, j or k (the voxel axis across the ROI's plane)");
}

}  // namespace voxray::cli
