#pragma once
// How a volume's voxel axes appear in the three slice views. Radiological convention, as
// in 3D Slicer, Horos and RadiAnt: axial and coronal views show the patient's right on the
// screen's left; axial has anterior at the top; coronal and sagittal have superior at the
// top; sagittal has anterior on the left. Each screen axis takes the voxel axis closest to
// the wanted patient (LPS) axis, so flipped or permuted acquisitions display correctly.
#include <array>
#include <string>

#include <glm/glm.hpp>

#include "no_qt.h"

namespace voxray {
struct Volume;
}

namespace voxray {

enum class Orientation { Axial, Coronal, Sagittal };
const char* toString(Orientation o);

struct SliceAxes {
  Orientation orientation = Orientation::Axial;  // the view these axes belong to
  int uAxis = 0;                                 // voxel axis along the screen's x (left to right)
  int vAxis = 1;                                 // voxel axis along the screen's y (top to bottom)
  int nAxis = 2;                                 // voxel axis across the slice: the slice index
  bool uFlip = false;  // true: voxel index grows towards the screen's left
  bool vFlip = false;  // true: voxel index grows towards the screen's top
  // Patient orientation letters at the screen's left, right, top and bottom edges.
  std::array<std::string, 4> labels;  // left, right, top, bottom
};

SliceAxes sliceAxes(const glm::dmat3& direction, Orientation o);

// A view's screen right, screen down and normal as patient (LPS) unit vectors: the rule
// above, which the slice views (through sliceAxes), the movie cine and voxray-cli slice
// share.
struct PatientAxes {
  glm::dvec3 right, down, normal;
};
PatientAxes patientAxes(Orientation o);

// Slice-pixel coordinates (u, v in voxel units from the screen's top left, continuous,
// pixel centres at k + 0.5) to a voxel position with the given slice index. On a rotated
// (oblique) view these are the coordinates of the acquisition plane before the rotation
// about the crosshair (crosshair_model.h).
glm::dvec3 sliceToVoxel(const SliceAxes& a, const glm::ivec3& dims, double u, double v,
                        double slice);
// The inverse, ignoring the slice coordinate: where a voxel position appears in a view.
glm::dvec2 voxelToSlice(const SliceAxes& a, const glm::ivec3& dims, const glm::dvec3& voxel);

// Patient position (LPS mm) of a voxel position, from the volume's origin and direction.
glm::dvec3 voxelToPatientMm(const Volume& v, const glm::dvec3& voxel);
// World position (LPS mm relative to the volume centre) as the 3D view and engine use it.
glm::dvec3 voxelToWorldMm(const Volume& v, const glm::dvec3& voxel);

}  // namespace voxray
