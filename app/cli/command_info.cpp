#include <iostream>
#include <optional>

#include "commands.h"
#include "info_json.h"
#include "input_options.h"
#include "json_text.h"
#include "terminal_text.h"
#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"
#include "voxray/io/volume_file.h"

namespace voxray::cli {

Run addInfoCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Describe a volume: dims, spacing, value range, warnings");
  auto in = std::make_shared<InputOptions>();
  auto json = std::make_shared<bool>(false);
  in->add(*cmd);
  cmd->add_flag("--json", *json, "machine-readable output on stdout");
  return [in, json] {
    std::optional<DicomListing> listing;
#ifdef VOXRAY_HAS_DICOM  // lean builds (VOXRAY_WITH_DICOM=OFF) read raw data only
    if (!in->input.empty() && !in->flags.count("raw-dims") && !isVolumeFile(in->input)) {
      try {
        listing = listDicomSeries(in->input);
      } catch (const Error&) {
        // Not DICOM, or broken: loading below gives the message that says why.
      }
    }
#endif
    Volume v = in->load();
    nlohmann::json j = infoJson(v, listing ? &*listing : nullptr);
    if (*json) {
      std::cout << jsonText(j) << "\n";
      return 0;
    }
    std::cout << "dims        " << v.dims.x << " x " << v.dims.y << " x " << v.dims.z << "\n"
              << "spacing     " << v.spacingMm.x << " x " << v.spacingMm.y << " x " << v.spacingMm.z
              << " mm\n"
              << "extent      " << v.extentMm().x << " x " << v.extentMm().y << " x "
              << v.extentMm().z << " mm\n"
              << "values      " << j["hu_min"].get<double>() << " ... " << j["hu_max"].get<double>()
              << " " << terminalText(v.unit) << "\n"
              << "sample type " << terminalText(v.sourceType) << " (stored as int16, "
              << (v.byteSize() >> 20) << " MiB)\n";
    // Strings from the files go through terminalText: they may hold terminal controls.
    for (const auto& w : v.warnings) std::cout << "warning: " << terminalText(w) << "\n";
    if (listing) {
      std::cout << "series (" << listing->filesScanned << " files, " << listing->filesSkipped
                << " skipped):\n";
      for (const auto& s : listing->series)
        std::cout << (s.chosenByDefault ? " * " : "   ") << terminalText(s.selector) << "  "
                  << terminalText(s.modality) << "  " << s.dims.x << "x" << s.dims.y << "x"
                  << s.dims.z << "  " << terminalText(s.description)
                  << (s.isVolume ? "" : "  (" + terminalText(s.notVolumeReason) + ")") << "\n";
    }
    return 0;
  };
}

}  // namespace voxray::cli
