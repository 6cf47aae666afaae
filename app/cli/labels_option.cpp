#include "labels_option.h"

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "voxray/io/error.h"
#ifdef VOXRAY_HAS_SEGMENT_FILES
#include "voxray/io/segment_files.h"
#endif
#include "voxray/io/volume.h"

namespace voxray::cli {

namespace {

// Distinct colours for labels 1, 2, ... (then repeating): a raw map names no colours.
glm::vec3 paletteColour(int label) {
  static const std::array<glm::vec3, 8> kPalette = {{{0.90f, 0.20f, 0.20f},
                                                     {0.20f, 0.75f, 0.25f},
                                                     {0.25f, 0.45f, 0.95f},
                                                     {0.95f, 0.85f, 0.20f},
                                                     {0.20f, 0.85f, 0.90f},
                                                     {0.85f, 0.30f, 0.85f},
                                                     {0.95f, 0.55f, 0.15f},
                                                     {0.55f, 0.35f, 0.85f}}};
  return kPalette[size_t(label - 1) % kPalette.size()];
}

}  // namespace

void LabelsOption::add(CLI::App& cmd) {
  cmd.add_option("--labels-raw", raw,
                 "label map for dvr (uint8 per voxel, x fastest, on the volume's dims): each "
                 "label a segment in its own colour; see --segment-mask, --segment-blend");
  cmd.add_option("--labels", file,
                 "segmentation for dvr: NIfTI or .seg.nrrd label map on the volume's grid, or "
                 "a DICOM SEG of the volume's series (names and colours as stored)");
  cmd.add_option("--segment-surface", surfaces,
                 "labels L,... of --labels / --labels-raw drawn in dvr as smooth surfaces (the "
                 "mask filtered by a 1-voxel Gaussian, its 0.5 level) in the segment's colour "
                 "and opacity, instead of tinting the volume");
}

namespace {

// The segments --segment-surface names shown as surfaces.
Segmentation withSurfaces(Segmentation s, const std::string& list) {
  if (list.empty()) return s;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    int label = 0;
    try {
      size_t used = 0;
      label = std::stoi(item, &used);
      if (used != item.size()) label = 0;
    } catch (const std::exception&) {
      label = 0;
    }
    Segment* seg = nullptr;
    for (Segment& x : s.segments)
      if (label > 0 && x.label == label) seg = &x;
    if (!seg)
      throw inputError("--segment-surface: '" + item +
                       "' is not a label of the segmentation's segments (1 ... 255, comma-"
                       "separated, each holding voxels)");
    seg->display3d = Segment::Display3d::Surface;
  }
  return s;
}

}  // namespace

std::optional<Segmentation> LabelsOption::load(const Volume& v) const {
  if (!raw.empty() && !file.empty())
    throw inputError("give --labels FILE or --labels-raw FILE, not both");
  if (!file.empty()) {
#ifdef VOXRAY_HAS_SEGMENT_FILES
    return withSurfaces(readSegmentationFile(file, v), surfaces);
#else
    throw inputError("--labels needs Voxray built with its NIfTI, Teem and DICOM parts");
#endif
  }
  if (raw.empty()) {
    if (!surfaces.empty()) throw inputError("--segment-surface needs --labels or --labels-raw");
    return std::nullopt;
  }
  Segmentation s = emptySegmentation(v);
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(raw, ec);
  if (ec) throw inputError("--labels-raw " + raw + ": cannot read it (" + ec.message() + ")");
  if (bytes != s.labels.size())
    throw inputError("--labels-raw " + raw + ": it has " + std::to_string(bytes) +
                     " bytes; a uint8 label map of this volume (" + std::to_string(v.dims.x) +
                     " x " + std::to_string(v.dims.y) + " x " + std::to_string(v.dims.z) +
                     ") has " + std::to_string(s.labels.size()));
  std::ifstream in(raw, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(s.labels.data()), std::streamsize(s.labels.size())))
    throw inputError("--labels-raw " + raw + ": reading it stopped early");
  std::array<bool, 256> present{};
  for (uint8_t l : s.labels) present[l] = true;
  for (int l = 1; l < 256; ++l) {
    if (!present[size_t(l)]) continue;
    Segment seg;
    seg.label = uint8_t(l);
    seg.name = "Segment " + std::to_string(l);
    seg.colour = paletteColour(l);
    s.segments.push_back(seg);
  }
  return withSurfaces(std::move(s), surfaces);
}

}  // namespace voxray::cli
