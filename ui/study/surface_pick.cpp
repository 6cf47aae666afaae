#include "surface_pick.h"

#include <cmath>

#include "voxray/engine/step.h"

namespace voxray {

std::optional<glm::dvec3> surfaceHitAt(const std::vector<glm::vec4>& hits, glm::ivec2 size,
                                       glm::ivec2 pixel) {
  if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.x || pixel.y >= size.y) return std::nullopt;
  const size_t i = size_t(pixel.y) * size_t(size.x) + size_t(pixel.x);
  if (i >= hits.size() || hits[i].w < 0.0F) return std::nullopt;
  return glm::dvec3(hits[i]);
}

namespace {
constexpr double kPickStepVoxels = 0.5;  // the longest dvr step of a pick (surface_pick.h)
}  // namespace

RenderParams pickFrameParams(RenderParams p, double minSpacingMm) {
  const double longest = stepMmOf(kPickStepVoxels, minSpacingMm);
  if (p.mode == Mode::Dvr && effectiveStepMm(p, minSpacingMm) > longest) p.stepMm = longest;
  return p;
}

std::string pickMissMessage(const RenderParams& p) {
  switch (p.mode) {
    case Mode::Iso:
      return "No surface under the cursor to measure on";
    case Mode::Dvr:
      // The kernel's threshold (DVR_HIT_ALPHA, kernels/march/hit_output.cl) is 0.5.
      if (p.earlyTermination < 0.5)
        return "Early termination stops rays at " +
               std::to_string(int(std::lround(100.0 * p.earlyTermination))) +
               " % opacity, before the 50 % a 3D pick needs: raise it to measure in 3D";
      return "Nothing under the cursor reaches 50 % opacity to measure on";
    case Mode::Mip:
      break;
  }
  return "3D measuring picks the iso surface or dvr's first opaque point: switch the mode to iso "
         "or dvr";
}

}  // namespace voxray
