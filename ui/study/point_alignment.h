#pragma once
// Rigid alignment of a moving volume onto a fixed one from point pairs (issue 36, compare):
// the least-squares rotation and translation (Kabsch / Horn: the SVD of the pairs' cross-
// covariance, Eigen's JacobiSVD) taking each moving point (LPS mm) onto its fixed partner.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "no_qt.h"

namespace voxray {

struct RigidAlignment {
  glm::dmat4 movingToFixed{1.0};    // fixed point = movingToFixed * moving point (mm)
  std::vector<double> residualsMm;  // per pair, after alignment
  double rmsMm = 0.0, maxMm = 0.0;  // of the residuals
};

// FIXED[i] and MOVING[i] are one landmark in each volume (LPS mm). Throws Error (Input) when
// the counts differ, there are fewer than three pairs, or either set's points are (nearly)
// collinear: then no rotation about their line is determined.
RigidAlignment alignPointPairs(const std::vector<glm::dvec3>& fixed,
                               const std::vector<glm::dvec3>& moving);

// "RMS 0.42 mm, largest 0.80 mm (4 pairs)": what the compare panel shows.
std::string formatAlignment(const RigidAlignment& a);

}  // namespace voxray
