#pragma once
// Fused dvr (issue 36): a second volume (PET on CT, ...) raycast in the same pass as the
// first, each dvr sample classifying both at one patient point (kernels/classification/
// overlay.cl); in mip its largest value along each ray over the volume's grey. The overlay keeps
// its own grid: its origin, spacing and LPS direction place it, so it need not share the base's
// dims or voxels.
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/transfer_function.h"

namespace voxray {

struct Volume;

// The affine map from BASE's voxel coordinates (centres at integers) to OVERLAY's, through
// patient space (LPS mm): overlay voxel = inverse(overlay grid) * base grid * base voxel.
glm::dmat4 overlayVoxelMap(const Volume& base, const Volume& overlay);

// What the user should hear before trusting the fused picture: that the two volumes do not
// name one DICOM Frame of Reference (then their patient coordinates need not agree; the
// overlay is placed by them anyway). Empty when both name the same one.
std::vector<std::string> overlayWarnings(const Volume& base, const Volume& overlay);

// Throws Error (Device) saying how many bytes the overlay needs and what to do, when its
// voxels exceed MAX_ALLOC bytes (one allocation of the device).
void checkOverlayFits(size_t overlayBytes, size_t maxAllocBytes);

// A table for the overlay from a window (physical units of the overlay, LO < HI) and a
// colour map ("hot-iron", "rainbow", "grey"): transparent at and below LO, opacity rising
// linearly to OPACITY (per reference step) at HI and constant beyond, the colour running
// through the map from LO to HI. Throws Error (Input) for an unknown map or LO >= HI.
TransferFunction overlayWindowTable(double lo, double hi, const std::string& colormap,
                                    double opacity);
// TF with every opacity times FACTOR (clamped to 0 ... 1): --overlay-opacity on a preset.
TransferFunction scaledOpacity(TransferFunction tf, double factor);

// What fused mip lays over the grey where the overlay's largest value along a ray shows: the
// table's largest opacity (0 ... 1; for a window's table its opacity at and above HI, the
// user's), as the slice views lay the colour map at the user's opacity.
double overlayMipOpacity(const Lut& lut);

// The overlay's classification in double precision, as overlay.cl (the reference renderer):
// trilinear in the overlay's voxels (clamped to its edge voxels), transparent outside its box.
struct OverlayClassifier {
  const Volume* overlay = nullptr;
  Lut lut;
  glm::dmat4 map{1.0};  // overlayVoxelMap
  OverlayClassifier(const Volume& base, const Volume& overlay, const TransferFunction& tf);
  glm::dvec4 at(const glm::dvec3& baseVoxel) const;
  // The stored value there (trilinear); false outside the overlay's box.
  bool value(const glm::dvec3& baseVoxel, double& stored) const;
  // Fused mip (overlay.cl's overlay_mip): the overlay's largest VALUE along a ray over the
  // volume's mip GREY: the table's colour there at overlayMipOpacity, as the slice views
  // fuse; GREY where the table shows nothing there.
  glm::dvec3 overMip(const glm::dvec3& grey, double largest) const;
};

}  // namespace voxray
