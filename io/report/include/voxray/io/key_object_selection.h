#pragma once
// Key images: a Key Object Selection document (TID 2010) that marks slices of a volume read
// from DICOM, by the SOP Instance UIDs of their source files, in the volume's study.
#include <string>
#include <vector>

#include "voxray/io/volume.h"

namespace voxray {

struct KeyImagesInfo {
  std::string description;  // Key Object Description (free text); empty: none
};

// Writes the KOS for SLICES (k indices of V, each once, in the order given) into PATH and
// returns its SOP Instance UID. Throws Error (Input) for a volume without per-slice source
// UIDs (not DICOM, or resampled), no slices or a slice outside 0..k-1, (Output) when PATH
// cannot be written.
std::string writeKeyObjectSelection(const std::string& path, const Volume& v,
                                    const std::vector<int>& slices, const KeyImagesInfo& info = {});

}  // namespace voxray
