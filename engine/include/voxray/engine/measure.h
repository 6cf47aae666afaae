#pragma once
// Measurements on a volume in physical space: distances and angles between points given in
// voxel coordinates (centres at integers, continuous), and region statistics over the
// voxels of one index plane. Every length goes through the volume's spacing and direction
// (voxelToPatient), so anisotropic voxels, oblique and tilt-resampled series measure true
// millimetres. Shared by the workstation's tools and `voxray-cli measure`.
//
// Undefined results are empty optionals, never NaN: a zero-length arm has no angle, a
// region with no voxel (zero area, or outside the volume) has no mean.
#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace voxray {

struct Volume;

// Patient position (LPS mm) of a voxel position.
glm::dvec3 voxelToPatient(const Volume& v, const glm::dvec3& voxel);
// Patient direction (LPS mm) to voxel position: the inverse of voxelToPatient.
glm::dvec3 patientToVoxel(const Volume& v, const glm::dvec3& patientMm);
// True when the point lies in the volume's box (voxel cells: [-0.5, n - 0.5] per axis).
bool insideVolume(const Volume& v, const glm::dvec3& voxel);

// Distance in mm between two voxel positions (0 for coincident points).
double distanceMm(const Volume& v, const glm::dvec3& a, const glm::dvec3& b);
// Angle in degrees at VERTEX between the arms to A and C, in patient space; none when an
// arm has zero length.
std::optional<double> angleDeg(const Volume& v, const glm::dvec3& a, const glm::dvec3& vertex,
                               const glm::dvec3& c);

enum class RoiShape { Ellipse, Rect };

// A region in the index plane across NORMAL_AXIS (0 = i, 1 = j, 2 = k) through the slice
// nearest to corner A's coordinate on that axis; A and B are opposite corners of the shape's
// bounding box (voxel positions; their coordinate on NORMAL_AXIS other than A's is ignored).
struct PlaneRoi {
  RoiShape shape = RoiShape::Ellipse;
  int normalAxis = 2;
  glm::dvec3 a{0.0}, b{0.0};
};

// The pixel rule: a voxel of the plane belongs to the region when its centre lies inside
// the shape or on its boundary (ellipse: ((x-cx)/rx)^2 + ((y-cy)/ry)^2 <= 1 in mm, with a
// relative tolerance of 1e-9 for rounding). Voxels outside the volume never count.
struct RoiStats {
  size_t pixels = 0;
  double areaMm2 = 0.0;  // the shape's own area (pi rx ry, or w h), not the pixel count's
  std::optional<double> mean, sd, min, max;  // physical units; none without a pixel
};
// SD is the sample standard deviation (n - 1); none for a single pixel.
RoiStats roiStats(const Volume& v, const PlaneRoi& roi);
// The voxels of the region by the same pixel rule, in slice order (rows, then columns).
std::vector<glm::ivec3> roiPixels(const Volume& v, const PlaneRoi& roi);

// Throws Error (Input) when AXIS is not 0, 1 or 2.
void checkPlaneAxis(int axis);

}  // namespace voxray
