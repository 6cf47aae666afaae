// voxray-cli segment: the workstation's threshold segmentation, headless. The operations run
// through segment_recipe.h, the one implementation the editor runs too, so the label map the
// CLI writes is the workstation's voxel for voxel.
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "commands.h"
#include "existing_output.h"
#include "input_options.h"
#include "segment_peak.h"
#include "voxray/io/error.h"
#include "voxray/io/segment_output.h"
#include "voxray/io/segment_recipe.h"
#include "voxray/io/segment_stats.h"

namespace voxray::cli {

namespace {

struct SegmentOptions {
  std::string threshold, seed, seedMm, name = "Segment", colour, output, statsJson;
  int connectivity = 6;
  bool keepLargest = false, fillHoles = false, force = false;
  // Meshes: RAS (Slicer's and most CAD's frame) instead of LPS, one file per segment, the
  // simplifier's target and the topology-preserving decimator.
  bool ras = false, perSegment = false, manifold = false, noSurfaceArea = false;
  size_t triangles = 500000;
  double marginMm = 0.0, smoothMm = 0.0;
};

// COUNT numbers separated by `sep`, each finite; throws naming the flag and the form.
std::vector<double> numbers(const std::string& text, char sep, size_t count, const char* flag,
                            const char* form) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, sep)) {
    std::istringstream p(part);
    double x = 0.0;
    char extra = 0;
    if (!(p >> x) || (p >> extra) || !std::isfinite(x))
      throw inputError(std::string(flag) + " '" + text + "': give " + form);
    out.push_back(x);
  }
  if (out.size() != count || (!text.empty() && text.back() == sep))
    throw inputError(std::string(flag) + " '" + text + "': give " + form);
  return out;
}

SegmentRecipe recipeOf(const SegmentOptions& o, const Volume& v) {
  SegmentRecipe r;
  const auto range = numbers(o.threshold, ',', 2, "--threshold", "LO,HI (physical values, HU)");
  r.threshold = {range[0], range[1]};
  if (o.connectivity != 6 && o.connectivity != 26)
    throw inputError("--connectivity " + std::to_string(o.connectivity) + ": give 6 or 26");
  r.connectivity = o.connectivity == 26 ? Connectivity::Full26 : Connectivity::Faces6;
  if (!o.seed.empty() && !o.seedMm.empty())
    throw inputError("give --seed (voxels) or --seed-mm (LPS mm), not both");
  if (!o.seed.empty()) {
    const auto s = numbers(o.seed, ':', 3, "--seed", "I:J:K (voxel indices)");
    for (double c : s)
      if (c != std::floor(c) || std::abs(c) > 1e6)
        throw inputError("--seed '" + o.seed + "': give I:J:K (whole voxel indices)");
    r.seed = glm::ivec3(int(s[0]), int(s[1]), int(s[2]));
  }
  if (!o.seedMm.empty()) {
    const auto s = numbers(o.seedMm, ',', 3, "--seed-mm", "X,Y,Z (LPS millimetres)");
    r.seed = seedFromMm(v, {s[0], s[1], s[2]});
  }
  r.keepLargest = o.keepLargest;
  r.fillHoles = o.fillHoles;
  r.marginMm = o.marginMm;
  if (o.smoothMm < 0.0) throw inputError("--smooth: give a kernel size of 0 mm or more");
  r.smoothMm = o.smoothMm;
  r.name = o.name;
  if (!o.colour.empty()) {
    const auto c = numbers(o.colour, ',', 3, "--colour", "R,G,B (0 to 255 each)");
    for (double x : c)
      if (x < 0.0 || x > 255.0)
        throw inputError("--colour '" + o.colour + "': give R,G,B (0 to 255 each)");
    r.colour = glm::vec3(float(c[0] / 255.0), float(c[1] / 255.0), float(c[2] / 255.0));
  }
  return r;
}

int runSegment(const InputOptions& in, const SegmentOptions& o) {
  if (o.output.empty() && o.statsJson.empty())
    throw inputError("segment: give -o OUT (a label map or mesh) and/or --stats-json FILE|-");
  // Refuse an existing output before the work, not after it.
  refuseExisting(o.output, o.force);
  if (o.statsJson != "-") refuseExisting(o.statsJson, o.force);
  const Volume v = in.load();
  const SegmentRecipe r = recipeOf(o, v);
  const Segmentation s = segmentationFromRecipe(v, r);
  if (!o.output.empty()) {
    SegmentOutputOptions out;
    out.force = o.force;
    out.mesh.coordinates = o.ras ? MeshCoordinates::Ras : MeshCoordinates::Lps;
    out.mesh.perSegment = o.perSegment;
    out.mesh.surface.targetTriangles = o.triangles;
    out.mesh.surface.preserveTopology = o.manifold;
    writeSegmentationOutput(o.output, s, v, out);
  }
  auto stats = allSegmentStats(s, v);
  addSuvPeaks(stats, s, v);  // a PET with its SUV attributes: the 1 cm³ sphere's SUVbw
  if (!o.statsJson.empty() && !o.noSurfaceArea) addSurfaceAreas(stats, s);
  if (o.statsJson == "-") {
    std::cout << statsJson(stats);
  } else if (!o.statsJson.empty()) {
    std::ofstream out(o.statsJson, std::ios::trunc);
    out << statsJson(stats);
    if (!out)
      throw outputError("Cannot write " + o.statsJson + ": check the folder and free space.");
  }
  if (o.statsJson != "-") {
    std::cout << r.name << ": " << stats[0].voxels << " voxels, " << stats[0].volumeMl << " mL";
    if (stats[0].suvPeak) std::cout << ", SUVpeak " << *stats[0].suvPeak << " SUVbw";
    if (!stats[0].peakNote.empty()) std::cout << ", no SUVpeak: " << stats[0].peakNote;
    std::cout << "\n";
  }
  return 0;
}

}  // namespace

Run addSegmentCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "segment",
      "Threshold segmentation as the workstation's editor: seeded region, islands, "
      "holes, margin, smoothing; writes the label map or mesh and statistics");
  auto in = std::make_shared<InputOptions>();
  auto o = std::make_shared<SegmentOptions>();
  in->add(*cmd);
  cmd->add_option("--threshold", o->threshold, "LO,HI: the range of values (HU) to take")
      ->required();
  cmd->add_option("--seed", o->seed, "I:J:K: keep the region connected to this voxel");
  cmd->add_option("--seed-mm", o->seedMm, "X,Y,Z: the seed as an LPS position in mm");
  cmd->add_option("--connectivity", o->connectivity,
                  "6 (faces) or 26 (faces, edges, corners) for the seed and islands")
      ->default_val(6);
  cmd->add_flag("--keep-largest", o->keepLargest, "keep only the largest island");
  cmd->add_flag("--fill-holes", o->fillHoles, "fill the cavities closed on every side");
  cmd->add_option("--margin", o->marginMm, "grow (> 0) or shrink (< 0) by MM millimetres");
  cmd->add_option("--smooth", o->smoothMm, "median smoothing with a kernel of MM millimetres");
  cmd->add_option("--name", o->name, "the segment's name (default Segment)");
  cmd->add_option("--colour", o->colour, "R,G,B 0-255: the segment's colour");
  cmd->add_option("-o,--output", o->output,
                  "OUT: .stl .obj .ply .nii .nii.gz .seg.nrrd .nrrd .dcm or .labels.raw");
  cmd->add_option("--stats-json", o->statsJson, "FILE or - (stdout): the segment's statistics");
  cmd->add_flag("--force", o->force, "replace existing output files");
  cmd->add_flag("--ras", o->ras, "meshes in RAS mm (Slicer, most CAD) instead of DICOM's LPS");
  cmd->add_flag("--per-segment", o->perSegment, "one mesh file per segment (OUT_LABEL_NAME.stl)");
  cmd->add_option("--triangles", o->triangles,
                  "simplify each mesh to at most N triangles (default 500000, 0 = keep all)");
  cmd->add_flag("--manifold", o->manifold,
                "topology-preserving decimation (VTK DecimatePro): a closed manifold mesh for "
                "printing, tens of seconds on a bone");
  cmd->add_flag("--no-surface-area", o->noSurfaceArea,
                "leave surface_mm2 out of --stats-json (it meshes each segment)");
  return [in, o] { return runSegment(*in, *o); };
}

}  // namespace voxray::cli
