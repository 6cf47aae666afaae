// voxray-cli tf: transfer-function files between Voxray's JSON and 3D Slicer's .vp, and the
// built-in presets as either (issue 35).
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "voxray/engine/render_params.h"
#include "voxray/engine/transfer_function.h"
#include "voxray/engine/volume_property.h"
#include "voxray/io/error.h"

namespace voxray::cli {

namespace {

struct TfOptions {
  std::string input, output;
  bool force = false;
};

constexpr const char* kPresetPrefix = "preset:";

// A file, or "preset:NAME": a built-in preset as a property (its table, linear, per voxel).
VolumeProperty readSource(const std::string& input) {
  if (input.rfind(kPresetPrefix, 0) == 0) {
    RenderParams p;
    applyPreset(p, findPreset(input.substr(std::string(kPresetPrefix).size())));
    if (p.mode != Mode::Dvr)
      throw inputError("preset '" + p.preset + "' is made for " + toString(p.mode) +
                       ", not dvr; a transfer function file holds a dvr table");
    return volumePropertyOf(p);
  }
  return readVolumePropertyFile(input);
}

}  // namespace

Run addTfCommand(CLI::App& app) {
  auto o = std::make_shared<TfOptions>();
  auto* tf = app.add_subcommand("tf", "Transfer-function files: Voxray .json and 3D Slicer .vp");
  tf->require_subcommand(1);
  auto* convert = tf->add_subcommand(
      "convert",
      "Read a transfer function (.json, .vp or preset:NAME) and write it as .json or .vp. "
      "Slicer's .vp has no curve, unit distance or name: a smooth curve is written as "
      "straight lines within 1/1024 of it");
  convert->add_option("input", o->input, "FILE.json, FILE.vp or preset:NAME")->required();
  convert->add_option("output", o->output, "FILE.json or FILE.vp")->required();
  convert->add_flag("--force", o->force, "overwrite OUTPUT if it exists");
  return [o] {
    VolumeProperty vp = readSource(o->input);
    std::error_code ec;
    if (!o->force && std::filesystem::exists(o->output, ec))
      throw outputError(o->output + " exists; give --force to overwrite it");
    bool toSlicer = std::filesystem::path(o->output).extension() == ".vp";
    if (toSlicer && vp.unitDistanceMm > 0.0)
      std::cerr << "voxray-cli: note: Slicer's .vp has no unit distance; its opacities are "
                   "read back per smallest voxel spacing, not per "
                << vp.unitDistanceMm << " mm\n";
    writeVolumePropertyFile(vp, o->output);
    std::cout << o->output << ": " << vp.color.size() << " colour and " << vp.opacity.size()
              << " opacity points written\n";
    return 0;
  };
}

}  // namespace voxray::cli
