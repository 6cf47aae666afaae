// voxray-cli tf: transfer-function files between Voxray's JSON and 3D Slicer's .vp, and the
// built-in presets as either (issue 35).
#include <cctype>
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "existing_output.h"
#include "voxray/engine/render_params.h"
#include "voxray/engine/transfer_function.h"
#include "voxray/engine/volume_property.h"
#include "voxray/io/error.h"

namespace voxray::cli {

namespace {

struct TfOptions {
  std::string input, output, name, list;
  bool force = false;
};

bool isPresetList(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".xml";
}

constexpr const char* kPresetPrefix = "preset:";

// A file, a Slicer preset list (.xml) with NAME, or "preset:NAME": a built-in preset as a
// property (its table, linear, per voxel).
VolumeProperty readSource(const std::string& input, const std::string& name) {
  if (isPresetList(input)) {
    if (name.empty())
      throw inputError(input + " is a preset list: give --name (voxray-cli tf list " + input +
                       " shows them)");
    return findProperty(readSlicerPresetFile(input), name, input);
  }
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
      "Read a transfer function (.json, .vp, a Slicer presets.xml with --name, or "
      "preset:NAME) and write it as .json or .vp. "
      "Slicer's .vp has no curve, unit distance or name: a smooth curve is written as "
      "straight lines within 1/1024 of it");
  convert->add_option("input", o->input, "FILE.json, FILE.vp, presets.xml or preset:NAME")
      ->required();
  convert->add_option("output", o->output, "FILE.json or FILE.vp")->required();
  convert->add_flag("--force", o->force, "overwrite OUTPUT if it exists");
  convert->add_option("--name", o->name, "which preset of a Slicer preset list (presets.xml)");
  auto* list = tf->add_subcommand("list", "The presets of a 3D Slicer preset list (presets.xml)");
  list->add_option("file", o->list, "presets.xml")->required();
  return [o, list] {
    if (list->parsed()) {
      for (const VolumeProperty& p : readSlicerPresetFile(o->list))
        std::cout << p.name << ": " << p.color.size() << " colour and " << p.opacity.size()
                  << " opacity points" << (hasGradientOpacity(p) ? ", gradient opacity" : "")
                  << "\n";
      return 0;
    }
    VolumeProperty vp = readSource(o->input, o->name);
    refuseExisting(o->output, o->force);
    bool toSlicer = std::filesystem::path(o->output).extension() == ".vp";
    if (toSlicer && vp.unitDistanceMm > 0.0)
      std::cerr << "voxray-cli: note: Slicer's .vp has no unit distance; its opacities are "
                   "read back per smallest voxel spacing, not per "
                << vp.unitDistanceMm << " mm\n";
    if (toSlicer && !vp.tf2d.empty())
      std::cerr << "voxray-cli: note: Slicer's .vp has no 2D transfer function; its "
                << vp.tf2d.primitives.size()
                << " primitives are dropped and the 1D colour and opacity are written\n";
    writeVolumePropertyFile(vp, o->output);
    std::cout << o->output << ": " << vp.color.size() << " colour and " << vp.opacity.size()
              << " opacity points written\n";
    return 0;
  };
}

}  // namespace voxray::cli
