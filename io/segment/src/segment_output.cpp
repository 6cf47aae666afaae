#include "voxray/io/segment_output.h"

#include <cctype>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "voxray/io/error.h"
#include "voxray/io/segment_mesh.h"
#include "voxray/io/segment_stats.h"
#ifdef VOXRAY_HAS_SEGMENT_FILES
#include "voxray/io/segment_files.h"
#endif
#include "voxray/io/segmentation_check.h"

namespace voxray {
namespace {

bool endsWith(const std::string& s, const std::string& end) {
  if (s.size() < end.size()) return false;
  for (size_t i = 0; i < end.size(); ++i)
    if (std::tolower((unsigned char)s[s.size() - end.size() + i]) != end[i]) return false;
  return true;
}

void refuseExisting(const std::string& path, bool force) {
  std::error_code ec;
  if (!force && std::filesystem::exists(path, ec))
    throw outputError(path + " exists: give --force to replace it, or another name.");
}

}  // namespace

std::string labelsRawSidecar(const std::string& rawPath) {
  const std::string stem = rawPath.substr(0, rawPath.size() - std::string(".labels.raw").size());
  return stem + ".labels.json";
}

void writeLabelsRaw(const std::string& path, const Segmentation& s, bool force) {
  checkSegmentation(s);
  const std::string sidecar = labelsRawSidecar(path);
  refuseExisting(path, force);
  refuseExisting(sidecar, force);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(s.labels.data()), std::streamsize(s.labels.size()));
    if (!out) throw outputError("Cannot write " + path + ": check the folder and free space.");
  }
  const auto& g = s.grid;
  nlohmann::json j;
  j["format"] = "voxray labels raw: uint8, x fastest, then y, then z";
  j["dims"] = {g.dims.x, g.dims.y, g.dims.z};
  j["spacing_mm"] = {g.spacingMm.x, g.spacingMm.y, g.spacingMm.z};
  j["origin_lps_mm"] = {g.originMm.x, g.originMm.y, g.originMm.z};
  j["direction"] = nlohmann::json::array();
  for (int c = 0; c < 3; ++c)
    j["direction"].push_back({g.direction[c].x, g.direction[c].y, g.direction[c].z});
  j["segments"] = nlohmann::json::array();
  for (const auto& seg : s.segments)
    j["segments"].push_back({{"label", seg.label},
                             {"name", seg.name},
                             {"colour", {seg.colour.r, seg.colour.g, seg.colour.b}},
                             {"opacity", seg.opacity},
                             {"visible", seg.visible}});
  std::ofstream out(sidecar, std::ios::trunc);
  out << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  if (!out) throw outputError("Cannot write " + sidecar + ": check the folder and free space.");
}

void writeSegmentationOutput(const std::string& path, const Segmentation& s, const Volume& v,
                             bool force) {
  SegmentOutputOptions options;
  options.force = force;
  writeSegmentationOutput(path, s, v, options);
}

void writeSegmentationOutput(const std::string& path, const Segmentation& s, const Volume& v,
                             const SegmentOutputOptions& options) {
  checkSegmentation(s);
  checkSameGrid(s, v);
  if (endsWith(path, ".labels.raw")) return writeLabelsRaw(path, s, options.force);
  if (endsWith(path, ".stl") || endsWith(path, ".obj") || endsWith(path, ".ply")) {
    MeshFileOptions mesh = options.mesh;
    mesh.overwrite = options.force;
    return writeMeshFile(path, s, {}, mesh);
  }
#ifdef VOXRAY_HAS_SEGMENT_FILES
  if (endsWith(path, ".nii") || endsWith(path, ".nii.gz"))
    return writeSegmentationNifti(path, s, options.force);
  if (endsWith(path, ".nrrd")) return writeSegNrrd(path, s, options.force);
  if (endsWith(path, ".dcm")) {
    DicomSegOptions seg;
    seg.force = options.force;
    seg.seriesDescription = options.segSeriesDescription;
    writeDicomSeg(path, s, v.study, seg);
    return;
  }
#endif
  for (const char* ext : {".nii", ".nii.gz", ".nrrd", ".dcm"})
    if (endsWith(path, ext))
      throw outputError(std::string("Writing ") + ext + " files needs Voxray built with its " +
                        "NIfTI, Teem and DICOM parts: write .stl or .labels.raw instead.");
  throw inputError(path +
                   ": give an output ending in .stl, .obj, .ply (surface), .nii, .nii.gz, "
                   ".seg.nrrd, .nrrd (label map), .dcm (DICOM SEG) or .labels.raw (raw labels).");
}

void addSurfaceAreas(std::vector<SegmentStats>& stats, const Segmentation& s) {
  SurfaceOptions unsimplified;
  unsimplified.targetTriangles = 0;
  for (auto& st : stats)
    if (st.voxels > 0) st.surfaceMm2 = makeSurface(s, st.label, unsimplified).areaMm2;
}

}  // namespace voxray
