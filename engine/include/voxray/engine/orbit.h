#pragma once
// A 360-degree orbit of the camera in N frames: what `voxray-cli bench` times and what
// movies show.
#include "voxray/engine/render_params.h"

namespace voxray {

// Azimuth: around the patient's long axis, from anterior. Elevation: around the
// anterior-posterior axis, from inferior through the patient's left and superior, which
// is the orbit VTK's Camera::Azimuth makes around an axial stack given to it without
// orientation with slice 1 at the top (the peer benchmark, docs/bench).
enum class Orbit { Azimuth, Elevation };

// The camera of frame FRAME of FRAMES (frame 0 at the orbit's start, FRAMES at 360 degrees).
void orbitCamera(CameraParams& c, Orbit orbit, int frame, int frames);

}  // namespace voxray
