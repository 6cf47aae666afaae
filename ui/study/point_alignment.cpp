#include "point_alignment.h"

#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

#include "voxray/io/error.h"

namespace voxray {

namespace {
// Points apart by less than this (mm) across their best-fit line count as on the line: far
// below a voxel, far above rounding of millimetre coordinates.
constexpr double kCollinearMm = 1e-3;

Eigen::Vector3d toEigen(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

// The second singular value of the centred points: their spread off their best-fit line.
double spreadOffLine(const Eigen::Matrix3Xd& centred) {
  Eigen::JacobiSVD<Eigen::Matrix3Xd> svd(centred);
  return svd.singularValues()(1) / std::sqrt(double(centred.cols()));
}
}  // namespace

RigidAlignment alignPointPairs(const std::vector<glm::dvec3>& fixed,
                               const std::vector<glm::dvec3>& moving) {
  if (fixed.size() != moving.size())
    throw inputError("alignment: " + std::to_string(fixed.size()) +
                     " points in the left view but " + std::to_string(moving.size()) +
                     " in the right; give each point its partner");
  const auto n = Eigen::Index(fixed.size());
  if (n < 3)
    throw inputError("alignment needs at least three point pairs, got " + std::to_string(n) +
                     "; add pairs of the same landmark in both views");
  Eigen::Matrix3Xd f(3, n), m(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    f.col(i) = toEigen(fixed[size_t(i)]);
    m.col(i) = toEigen(moving[size_t(i)]);
  }
  const Eigen::Vector3d fc = f.rowwise().mean(), mc = m.rowwise().mean();
  f.colwise() -= fc;
  m.colwise() -= mc;
  if (spreadOffLine(f) < kCollinearMm || spreadOffLine(m) < kCollinearMm)
    throw inputError(
        "alignment: the points lie on one line, which leaves the rotation about it open; "
        "pick landmarks that span a plane (at least one off the line of the others)");
  // Kabsch: H = M F^T = U S V^T, R = V diag(1, 1, d) U^T with d = sign(det(V U^T)) so that R
  // is a rotation, not a reflection.
  const Eigen::Matrix3d h = m * f.transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d u = svd.matrixU(), v = svd.matrixV();
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (v * u.transpose()).determinant() < 0 ? -1.0 : 1.0;
  const Eigen::Matrix3d r = v * d * u.transpose();
  const Eigen::Vector3d t = fc - r * mc;

  RigidAlignment out;
  for (int c = 0; c < 3; ++c) {
    for (int row = 0; row < 3; ++row) out.movingToFixed[c][row] = r(row, c);
    out.movingToFixed[3][c] = t(c);
  }
  double sum = 0.0;
  for (size_t i = 0; i < fixed.size(); ++i) {
    const glm::dvec3 p(out.movingToFixed * glm::dvec4(moving[i], 1.0));
    const double e = glm::length(p - fixed[i]);
    out.residualsMm.push_back(e);
    sum += e * e;
    out.maxMm = std::max(out.maxMm, e);
  }
  out.rmsMm = std::sqrt(sum / double(fixed.size()));
  return out;
}

std::string formatAlignment(const RigidAlignment& a) {
  char text[96];
  std::snprintf(text, sizeof text, "RMS %.2f mm, largest %.2f mm (%zu pairs)", a.rmsMm, a.maxMm,
                a.residualsMm.size());
  return text;
}

}  // namespace voxray
