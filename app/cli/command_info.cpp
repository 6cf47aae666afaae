#include <chrono>
#include <iostream>
#include <optional>
#include <sstream>

#include "commands.h"
#include "info_json.h"
#include "input_options.h"
#include "json_text.h"
#include "terminal_text.h"
#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"
#include "voxray/io/ome_zarr.h"
#include "voxray/io/volume_file.h"
#ifdef VOXRAY_HAS_DICOM  // the PACS client's library, which reads OME-Zarr URLs too
#include "voxray/io/zarr_url.h"
#endif

namespace voxray::cli {

namespace {

std::string physicalRange(const Volume& v) {
  const ValueRange r = storedRange(v);
  const double a = v.toPhysical(r.min), b = v.toPhysical(r.max);
  std::ostringstream out;
  out << std::min(a, b) << " ... " << std::max(a, b) << " " << terminalText(v.unit);
  if (v.suv)
    out << " (" << v.suv->toSuv(std::min(a, b)) << " ... " << v.suv->toSuv(std::max(a, b)) << " "
        << v.suv->unit << ")";
  return out.str();
}

int describeTimePoints(const InputOptions& in, bool json) {
  if (in.flags.count("time"))
    throw inputError("info: give --all-time-points or --time K, not both");
  const auto start = std::chrono::steady_clock::now();
#ifdef VOXRAY_HAS_DICOM
  const std::vector<Volume> all = loadVolumeSeriesOrUrl(in.input, in.loadOptions());
#else
  const std::vector<Volume> all = loadVolumeSeries(in.input, in.loadOptions());
#endif
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  size_t bytes = 0;
  for (const auto& v : all) bytes += v.byteSize();
  if (json) {
    nlohmann::json j = {{"time_points", all.size()},
                        {"bytes", bytes},
                        {"load_seconds", seconds},
                        {"volumes", nlohmann::json::array()}};
    for (const auto& v : all) j["volumes"].push_back(timePointJson(v));
    std::cout << jsonText(j) << "\n";
    return 0;
  }
  std::cout << all.size() << " time point(s), " << (bytes >> 20) << " MiB, loaded in " << seconds
            << " s\n";
  for (const auto& v : all)
    std::cout << "time " << v.timePoint << "  " << v.dims.x << " x " << v.dims.y << " x "
              << v.dims.z << "  " << physicalRange(v) << "\n";
  return 0;
}

}  // namespace

Run addInfoCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Describe a volume: dims, spacing, value range, warnings");
  auto in = std::make_shared<InputOptions>();
  auto json = std::make_shared<bool>(false);
  auto allTimes = std::make_shared<bool>(false);
  in->add(*cmd);
  cmd->add_flag("--json", *json, "machine-readable output on stdout");
  cmd->add_flag("--all-time-points", *allTimes,
                "4D: load every time point and describe each (dims, value range)");
  return [in, json, allTimes] {
    if (*allTimes) return describeTimePoints(*in, *json);
    std::optional<DicomListing> listing;
#ifdef VOXRAY_HAS_DICOM  // lean builds (VOXRAY_WITH_DICOM=OFF) read raw data only
    if (!in->input.empty() && !in->flags.count("raw-dims") && !isVolumeFile(in->input) &&
        !isOmeZarr(in->input) && !isUrl(in->input)) {
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
              << "values      " << physicalRange(v) << "\n"
              << "sample type " << terminalText(v.sourceType) << " (stored as int16, "
              << (v.byteSize() >> 20) << " MiB)\n";
    if (v.timePoints > 1)
      std::cout << "time point  " << v.timePoint << " of 0-" << v.timePoints - 1 << "\n";
    if (v.suv) std::cout << "suv         " << v.suv->unit << " = Bq/mL x " << v.suv->factor << "\n";
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
