#pragma once
// Edits of a label map (paint, erase, a mask from an operation), each returning the patch
// that undoes it: the edited box with the labels it held. Swapping a patch in undoes the edit
// and leaves the patch holding what redoes it.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/io/segment_mask.h"
#include "voxray/io/segmentation.h"

namespace voxray {

// What an edit may change. Painting a segment takes background voxels and its own; with
// overwriteOthers it also takes the voxels of other segments (otherwise they are kept).
struct EditPolicy {
  bool overwriteOthers = false;
};

// The voxels [lo, hi) of a box and the labels they held; empty when nothing changed.
struct LabelPatch {
  glm::ivec3 lo{0}, hi{0};
  std::vector<uint8_t> labels;
  bool empty() const { return labels.empty(); }
};

// Puts the patch's labels into the map and the map's old labels into the patch: the first
// swap undoes an edit, the next redoes it. Throws an internal Error when the box is outside.
void swapPatch(Segmentation& s, LabelPatch& p);

// Paints `label` into a ball of radius mm (physical: an ellipsoid of voxels on an anisotropic
// grid) centred at a voxel position (fractional index): every voxel whose centre lies within
// the radius. Erasing sets such voxels of `label` to 0 (label 0: every segment's).
LabelPatch paintSphere(Segmentation& s, glm::dvec3 centre, double radiusMm, uint8_t label,
                       EditPolicy policy = {});
LabelPatch eraseSphere(Segmentation& s, glm::dvec3 centre, double radiusMm, uint8_t label);
// The same in one slice (axis 0 = i, 1 = j, 2 = k; the slice is the centre's index along it).
LabelPatch paintDisc(Segmentation& s, int axis, glm::dvec3 centre, double radiusMm, uint8_t label,
                     EditPolicy policy = {});
LabelPatch eraseDisc(Segmentation& s, int axis, glm::dvec3 centre, double radiusMm, uint8_t label);

// Makes `label`'s voxels exactly the mask (as far as the policy lets: voxels of other
// segments outside overwriteOthers stay theirs).
LabelPatch setMask(Segmentation& s, uint8_t label, const Mask& m, EditPolicy policy = {});

}  // namespace voxray
