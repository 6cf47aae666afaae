#pragma once
// Where the volume lives on the device: its own header, so that the device volume does not
// include the raycaster that chooses it.

namespace voxray {

enum class VolumeStorage { Auto, Buffer, Image3d };

}  // namespace voxray
