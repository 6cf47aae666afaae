#pragma once
// Synthetic volumes made in code: the embedded default volume and test volumes.
#include "voxray/io/volume.h"

namespace voxray {

// A CT-like 3D Shepp-Logan style head in HU: air (-1000) outside, a bone shell above
// 700 HU, soft tissue around 40 HU with small ventricles and lesions. size^3 voxels
// of 1 mm (256 by default: the volume Voxray shows when nothing is opened).
Volume makeHeadPhantom(int size = 256);

}  // namespace voxray
