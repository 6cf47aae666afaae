#pragma once
// Synthetic volumes made in code: the embedded default volume and test volumes.
#include "voxray/io/volume.h"

namespace voxray {

// A CT-like 3D Shepp-Logan style head in HU: air (-1000) outside, a bone shell above
// 700 HU, soft tissue around 40 HU with small ventricles and lesions. size^3 voxels of
// 256/size mm, so the box is always 256 mm (256 by default: the volume Voxray shows when
// nothing is opened). Direction is identity in LPS and the box is centred on (0,0,0): the
// nose points to -y (anterior), the top of the head to +z, and a bright lesion sits in the
// patient's LEFT hemisphere (+x) so that left/right mistakes show. Throws Error (Input) for
// size < 2 or size > 1024.
Volume makeHeadPhantom(int size = 256);

// The left-hemisphere lesion of the phantom (LPS mm, independent of size), for tests of
// orientation: a render or slice must show it on the patient's left.
struct PhantomLesion {
  glm::dvec3 centreMm;
  double radiusMm;
  double hu;
};
PhantomLesion headPhantomLeftLesion();

}  // namespace voxray
