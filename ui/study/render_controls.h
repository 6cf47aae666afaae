#pragma once
// Which of the Rendering group's controls change the 3D image, and what the group says about
// it: the iso range means something to iso only, MIP's window to mip only, the gradient to
// the shaded modes; and lighting cinematic path-traces every mode with the dvr
// classification, so that none of the three applies there (issue 41 item 11).
#include <string>

#include "no_qt.h"
#include "voxray/engine/render_params.h"

namespace voxray {

struct RenderControls {
  bool isoRange = false;   // Iso from / Iso to
  bool mipWindow = false;  // MIP window / MIP level
  bool gradient = false;   // the gradient estimator (shading and surface normals)
  // What the image is when it is not what the mode says ("" otherwise).
  std::string note;
};

RenderControls renderControlsFor(const RenderParams& p);

}  // namespace voxray
