// voxray-cli key-images: chosen slices of a DICOM series as a Key Object Selection document.
#include <iostream>
#include <sstream>

#include "commands.h"
#include "existing_output.h"
#include "input_options.h"
#include "voxray/io/error.h"
#include "voxray/io/key_object_selection.h"

namespace voxray::cli {

namespace {

struct KeyImagesOptions {
  std::string slices, output, description;
  bool force = false;
};

std::vector<int> parseSlices(const std::string& text) {
  std::vector<int> out;
  std::stringstream in(text);
  std::string s;
  while (std::getline(in, s, ',')) {
    size_t used = 0;
    int k = -1;
    try {
      k = std::stoi(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != s.size())
      throw inputError("--slices '" + text +
                       "': give slice indices (k, from 0) separated by commas");
    out.push_back(k);
  }
  return out;
}

int runKeyImages(const InputOptions& in, const KeyImagesOptions& o) {
  if (o.output.empty()) throw inputError("key-images: give -o KOS.dcm");
  const std::vector<int> slices = parseSlices(o.slices);
  refuseExisting(o.output, o.force);
  const Volume v = in.load();
  KeyImagesInfo info;
  info.description = o.description;
  const std::string uid = writeKeyObjectSelection(o.output, v, slices, info);
  std::cout << o.output << ": key object selection of " << slices.size() << " image"
            << (slices.size() == 1 ? "" : "s") << ", SOP Instance UID " << uid << "\n";
  return 0;
}

}  // namespace

Run addKeyImagesCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "key-images",
      "Mark slices of a DICOM series as key images (a Key Object Selection document)");
  auto in = std::make_shared<InputOptions>();
  auto o = std::make_shared<KeyImagesOptions>();
  in->add(*cmd);
  cmd->add_option("--slices", o->slices, "slice indices k (from 0), separated by commas")
      ->required();
  cmd->add_option("-o,--output", o->output, "the KOS file to write")->required();
  cmd->add_option("--description", o->description, "the Key Object Description (free text)");
  cmd->add_flag("--force", o->force, "overwrite an existing output file");
  return [in, o] { return runKeyImages(*in, *o); };
}

}  // namespace voxray::cli
