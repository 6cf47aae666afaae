#pragma once
// The clip box (the seed's "bounding box" cut) as six draggable faces. The box is stored
// in fractions of the volume's extent along i, j, k (RenderParams::clip); the handles live
// in world millimetres so they can be drawn over the 3D view and the slice views.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "no_qt.h"
#include "view_projection.h"
#include "voxray/engine/render_params.h"

namespace voxray {

// Face f lies across voxel axis f / 2, at the box's low (even f) or high (odd f) side.
constexpr int kFaceCount = 6;
inline int faceAxis(int face) { return face / 2; }
inline bool faceIsHigh(int face) { return face % 2 == 1; }

// The thinnest box allowed, as a fraction of the extent: a box must never turn inside out.
constexpr double kMinClipGap = 0.02;

// Moves one face to FRACTION (clamped to [0, 1] and at least kMinClipGap from its opposite).
void setClipFace(ClipBox& box, int face, double fraction);
double clipFace(const ClipBox& box, int face);

// For the index axes i, j, k: the patient directions each runs between, from the box's low
// face to its high face ("R–L" for an axis growing to the patient's left), the closest
// patient axis for an oblique one. DIRECTION: the volume's (columns: LPS unit vectors).
std::array<std::string, 3> clipAxisLabels(const glm::dmat3& direction);

// Voxel position of a fractional box coordinate (0 = outer edge of the first voxel).
glm::dvec3 fractionToVoxel(const glm::ivec3& dims, const glm::dvec3& fraction);
double voxelToFraction(int dims, double voxel);

// Centre of FACE in world mm (relative to the volume centre, as the 3D view uses).
glm::dvec3 clipFaceCentreWorld(const Volume& v, const ClipBox& box, int face);

// The face handle nearest to SCREEN within MAX_PIXELS, skipping faces seen edge-on.
std::optional<int> pickClipFace(const Volume& v, const ClipBox& box, const ViewProjection& view,
                                const glm::dvec2& screen, double maxPixels = 12.0);

// Drags FACE by a screen movement: the component along the face normal's screen direction
// moves the face; the rest is ignored. Returns the new box.
ClipBox dragClipFace(const Volume& v, const ClipBox& start, const ViewProjection& view, int face,
                     const glm::dvec2& screenDelta);

}  // namespace voxray
