#pragma once
// Patient orientation codes for data that carry none (raw stacks). A code names, for the
// voxel axes i, j, k in turn, the patient direction in which the index grows:
// L(eft), R(ight), A(nterior), P(osterior), S(uperior), I(nferior). "LPS" is the identity
// of DICOM's patient coordinates; an axial stack whose first slice is the top of the head
// is "LPI"; a sagittal stack with the face on the left, the crown at the top is "PIL".
#include <string>

#include <glm/glm.hpp>

namespace voxray {

// Direction matrix (columns: LPS unit vectors of i, j, k). Throws Error (Input) for a code
// that is not three letters naming three different patient axes.
glm::dmat3 directionFromAxesCode(const std::string& code);
// The closest code for a direction matrix (for display: "LPS", "LPI", ...).
std::string axesCodeFromDirection(const glm::dmat3& direction);

}  // namespace voxray
