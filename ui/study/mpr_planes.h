#pragma once
// Geometry of the oblique MPR planes (Qt-free maths, in patient LPS millimetres): each view's
// frame, rotations about a view's normal, where a plane cuts the volume's box (the 3D view's
// outlines), and the orientation letters of an oblique direction.
#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "no_qt.h"
#include "slice_geometry.h"

namespace voxray {
struct Volume;
}

namespace voxray {

// A view's plane as LPS unit vectors: screen x (right), screen y (down) and the direction in
// which its slice index grows (normal; +-(right x down)).
struct PlaneFrame {
  glm::dvec3 right{1, 0, 0}, down{0, 1, 0}, normal{0, 0, 1};
};

// The acquisition plane's frame of a view (slicePlane's axes): voxel axes with their flips.
PlaneFrame baseFrame(const glm::dmat3& direction, const SliceAxes& a);
PlaneFrame rotateFrame(const glm::dmat3& rotation, const PlaneFrame& f);

// Rotation by ANGLERAD about the unit AXIS, right-handed.
glm::dmat3 rotationAbout(const glm::dvec3& axis, double angleRad);
// The shortest rotation taking unit FROM onto unit TO (the identity when they agree).
glm::dmat3 rotationBetween(const glm::dvec3& from, const glm::dvec3& to);
// The rotation nearest to M (Gram-Schmidt), so that rounding never accumulates over drags.
glm::dmat3 orthonormalised(const glm::dmat3& m);
bool isIdentity(const glm::dmat3& m);

// The view and turn that show the plane of unit NORMAL (LPS): the view whose acquisition
// normal is nearest (either sign), turned by the shortest rotation onto it, so that an
// oblique plane keeps the nearest view's up and left. voxray-cli slice --normal uses it.
struct ObliqueView {
  Orientation orientation = Orientation::Axial;
  glm::dmat3 rotation{1.0};
};
ObliqueView viewForNormal(const glm::dmat3& direction, const glm::dvec3& normal);

// Voxel coordinates of a patient position (LPS mm): voxelToPatientMm's inverse.
glm::dvec3 patientMmToVoxel(const Volume& v, const glm::dvec3& mm);

// Where the plane through OTHERNORMAL's view cuts the view of frame F: the line's direction
// on screen (x right, y down, unit; screens show millimetres square). (0, 0) if parallel.
glm::dvec2 traceOnScreen(const PlaneFrame& f, const glm::dvec3& otherNormal);

// The polygon where the plane through CENTREVOXEL with unit NORMAL (LPS) cuts the volume's
// box (voxel cells, [-0.5, n - 0.5] per axis), in voxel coordinates; empty if it misses.
std::vector<glm::dvec3> planeInBox(const Volume& v, const glm::dvec3& centreVoxel,
                                   const glm::dvec3& normal);

// Patient letters of a direction, strongest first: "L" for (1, 0, 0), "LA" for
// (0.71, -0.71, 0). A component counts from 0.2 (about 12 degrees off the plane of the
// others), below which the direction reads as the nearer pure one.
std::string patientLetters(const glm::dvec3& dir);
// Letters at the screen's left, right, top and bottom edges of a view of frame F.
std::array<std::string, 4> frameLabels(const PlaneFrame& f);

}  // namespace voxray
