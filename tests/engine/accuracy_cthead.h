#pragma once
// CThead (Stanford, 256x256x113, 1x1x2 mm) from the shared data, loaded once; nullptr
// when the shared data are not beside the checkout (the tests then skip).
#include "voxray/engine/render_params.h"
#include "voxray/io/volume.h"

namespace voxray::test {

const Volume* cthead();
// CT-Bone dvr from the default camera at a test-sized image.
RenderParams ctheadDvr(int width = 128, int height = 96);

}  // namespace voxray::test
