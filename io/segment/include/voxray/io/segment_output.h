#pragma once
// Writes a segmentation to the file the user names, by its extension: surface meshes (.stl
// .obj .ply), label maps (.nii .nii.gz .seg.nrrd .nrrd), DICOM SEG (.dcm), or the raw label
// dump (.labels.raw with a .json sidecar beside it).
#include <string>
#include <vector>

#include "voxray/io/mesh_file.h"
#include "voxray/io/segment_stats.h"
#include "voxray/io/segmentation.h"

namespace voxray {

// Throws an output Error when the file exists and force is false, or it cannot be written;
// an input Error for an extension it does not know or a segmentation off the volume's grid.
void writeSegmentationOutput(const std::string& path, const Segmentation& s, const Volume& v,
                             bool force);

// What only some formats use: the meshes' frame, files and surface; the SEG's series.
struct SegmentOutputOptions {
  bool force = false;
  MeshFileOptions mesh;  // its overwrite is taken from force
  std::string segSeriesDescription = "Segmentation";
};
void writeSegmentationOutput(const std::string& path, const Segmentation& s, const Volume& v,
                             const SegmentOutputOptions& options);

// Fills each statistic's surfaceMm2 from the segment's smoothed surface (the mesh an STL would
// hold, before simplification, as Slicer's Segment Statistics takes it from its closed surface).
void addSurfaceAreas(std::vector<SegmentStats>& stats, const Segmentation& s);

// The raw dump: one uint8 label per voxel, x fastest, then y, then z; PATH.json beside it
// (PATH without ".labels.raw" + ".labels.json") says the grid and the segments.
void writeLabelsRaw(const std::string& path, const Segmentation& s, bool force);
// The sidecar's name for a .labels.raw path.
std::string labelsRawSidecar(const std::string& rawPath);

}  // namespace voxray
