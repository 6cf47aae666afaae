#pragma once
// From decoded stored samples to the int16 voxels of a Volume. Each slice keeps its own
// RescaleSlope/Intercept while decoding; when slices disagree they are brought onto one
// common scale afterwards, in place (no float copy of the volume).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "frame_header.h"

namespace voxray::dicom {

struct SliceScale {
  double slope = 1.0, intercept = 0.0;  // physical = voxel * slope + intercept
  int16_t min = 0, max = 0;             // voxel range in the slice
};

// Physical value that PixelPaddingValue maps to: air (-1024 HU) for CT, 0 otherwise.
double airValue(const std::string& modality);

// Writes VALUES (stored samples of one frame) into OUT as int16. Unsigned 16-bit samples
// are shifted by -32768 (and the intercept by +32768*slope) so nothing is clipped.
// Padding samples become AIR_PHYSICAL.
SliceScale storeSlice(const std::vector<int32_t>& values, const FrameHeader& h, double airPhysical,
                      int16_t* out);

// The same for the raw 16-bit words of one frame (a NativeFrames read), in place: WORDS
// become the slice, as storeSlice would write it from PixelFile's values of that frame.
SliceScale storeWords(uint16_t* words, size_t count, const FrameHeader& h, double airPhysical);

struct CommonScale {
  double slope = 1.0, intercept = 0.0;
  bool remap = false;   // slices need remapSlice
  std::string warning;  // set when slices had different rescale values
};

// One slope/intercept for the whole volume. The slope is the finest step among the slices
// (1 when all rescales are integral), so a non-integral slope keeps its precision.
CommonScale chooseCommonScale(const std::vector<SliceScale>& slices);

void remapSlice(int16_t* data, size_t count, const SliceScale& from, const CommonScale& to);

}  // namespace voxray::dicom
