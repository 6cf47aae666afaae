#pragma once
// Writes a segmentation to the file the user names, by its extension: surface meshes (.stl
// .obj .ply), label maps (.nii .nii.gz .seg.nrrd .nrrd), DICOM SEG (.dcm), or the raw label
// dump (.labels.raw with a .json sidecar beside it).
#include <string>

#include "voxray/io/segmentation.h"

namespace voxray {

// Throws an output Error when the file exists and force is false, or it cannot be written;
// an input Error for an extension it does not know or a segmentation off the volume's grid.
void writeSegmentationOutput(const std::string& path, const Segmentation& s, const Volume& v,
                             bool force);

// The raw dump: one uint8 label per voxel, x fastest, then y, then z; PATH.json beside it
// (PATH without ".labels.raw" + ".labels.json") says the grid and the segments.
void writeLabelsRaw(const std::string& path, const Segmentation& s, bool force);
// The sidecar's name for a .labels.raw path.
std::string labelsRawSidecar(const std::string& rawPath);

}  // namespace voxray
