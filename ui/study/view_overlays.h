#pragma once
// What the 3D view draws over its image (volume_overlay.h): the clip box's edges and face
// handles, the light handle, the outlines of the three slice planes. The user's choices in
// the panel, kept by RenderStateModel and saved in sessions.
#include "no_qt.h"

namespace voxray {

struct ViewOverlays {
  bool clipHandles = true;  // Clip → Handles in 3D view
  bool lightHandle = true;  // Light → Light handle in 3D view
  bool planes = false;      // Planes → Show planes in 3D view
  bool operator==(const ViewOverlays&) const = default;
};

}  // namespace voxray
