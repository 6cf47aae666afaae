#pragma once
// Analytic test volumes with exact ground truth, for the accuracy sweep and its tests:
// the Marschner-Lobb signal, spheres and tori as signed distance fields, and a ramp.
// Each volume is isotropic (1 mm voxels, identity direction, box centred on the origin);
// its values are the analytic field sampled at the voxel centres, stored as int16 with a
// slope fine enough that quantisation stays far below the errors being measured.
#include <string>

#include "voxray/io/volume.h"

namespace voxray {

enum class SyntheticShape {
  MarschnerLobb,  // fM = 6, alpha = 0.25 on [-1, 1]^3; -1000..1000 "HU", surface at 0
  Sphere,         // radius 0.35 (n - 1) voxels; value = 100 * signed distance (inside > 0)
  Torus,          // axis k, radii 0.3 (n - 1) and 0.12 (n - 1); value as for the sphere
  RampX           // value = 100 * (x - centre): trilinear reconstruction is exact
};

struct SyntheticSpec {
  SyntheticShape shape = SyntheticShape::MarschnerLobb;
  int size = 41;  // voxels along each axis
};

// The field behind a synthetic volume, in the volume's voxel coordinates (centres at
// integers). The iso surface is value == 0; inside is value > 0.
struct AnalyticField {
  SyntheticSpec spec;
  double value(const glm::dvec3& voxel) const;         // physical units
  glm::dvec3 gradient(const glm::dvec3& voxel) const;  // physical units per voxel
  // Distance to the surface in voxels: exact for the distance fields and the ramp; for
  // Marschner-Lobb a Newton projection along the gradient (error well below 1e-3 voxels
  // within the distances measured).
  double surfaceDistance(const glm::dvec3& voxel) const;
};

// Throws Error (Input) for a size below 2 or above 1024.
Volume makeSyntheticVolume(const SyntheticSpec& spec);

// "ml", "sphere", "torus" or "ramp"; throws Error (Input) naming the choices.
SyntheticShape parseSyntheticShape(const std::string& s);
const char* toString(SyntheticShape s);

}  // namespace voxray
