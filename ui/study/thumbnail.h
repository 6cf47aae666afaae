#pragma once
// A small grey picture of a volume's middle slice (as acquired: i across, j down) for the
// series picker, fitted into a square with the voxel aspect kept.
#include <string>

#include "no_qt.h"
#include "voxray/io/image.h"
#include "window_level.h"

namespace voxray {
struct Volume;
}

namespace voxray {

constexpr int kThumbnailSize = 64;

// A CT volume: a soft-tissue window (400/40) so every CT thumbnail looks alike. Anything
// else (MR, whose units differ from scanner to scanner; scouts and screen captures, which
// are often not in HU): the middle slice's own range.
WindowLevel defaultThumbnailWindow(const Volume& v, const std::string& modality, bool isVolume);

// SIZE x SIZE, black around the slice; an empty image for an empty volume.
Image middleSliceThumbnail(const Volume& v, const WindowLevel& wl, int size = kThumbnailSize);

}  // namespace voxray
