#pragma once
// Surface meshes of segments as files: STL (binary), OBJ with an MTL of the segments'
// colours, PLY (binary, face colours). One file for all, or one per segment. The coordinate
// frame, LPS or RAS millimetres, is written into each file (STL header, OBJ/PLY comments).
#include <cstdint>
#include <string>
#include <vector>

#include "voxray/io/segment_mesh.h"
#include "voxray/io/segmentation.h"

namespace voxray {

enum class MeshFormat { Stl, Obj, Ply };
enum class MeshCoordinates { Lps, Ras };  // RAS = LPS with x and y negated (Slicer's, most CAD)

struct MeshFileOptions {
  MeshCoordinates coordinates = MeshCoordinates::Lps;
  bool perSegment = false;  // true: PATH is a pattern; see perSegmentPath
  SurfaceOptions surface;
  bool overwrite = false;  // false: an existing file is an error and nothing is written
};

// The format PATH's extension names (.stl, .obj, .ply, any case); an input Error otherwise.
MeshFormat meshFormatFor(const std::string& path);

// "out/pelvis.stl" + segment 3 "Left femur" -> "out/pelvis_3_Left_femur.stl": the label keeps
// names unique; only letters, digits, '-' and '_' of the segment's name are kept.
std::string perSegmentPath(const std::string& path, const Segment& segment);

// Writes the surfaces of LABELS (empty = every visible segment that has voxels) to PATH.
// Throws an input Error for an unknown extension, a label with no segment, a segment without
// voxels, or an existing file without options.overwrite; an output Error when a file cannot
// be written. Files are written under temporary names and renamed at the end, so on an
// error nothing (not half a file) is left.
void writeMeshFile(const std::string& path, const Segmentation& s,
                   const std::vector<uint8_t>& labels, const MeshFileOptions& options = {});

}  // namespace voxray
