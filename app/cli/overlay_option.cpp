#include "overlay_option.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "voxray/engine/overlay.h"
#include "voxray/io/error.h"
#include "voxray/io/load.h"

namespace voxray::cli {

namespace {

// "LO,HI" in the overlay's display units (SUV where it has an SUV scale).
std::pair<double, double> parseWindow(const std::string& s) {
  std::istringstream in(s);
  double lo = 0.0, hi = 0.0;
  char comma = 0;
  if (!(in >> lo >> comma >> hi) || comma != ',' || !(in >> std::ws).eof())
    throw inputError("--overlay-window: expected LO,HI (e.g. 2.5,10), got '" + s + "'");
  return {lo, hi};
}

}  // namespace

void OverlayOption::add(CLI::App& cmd) {
  cmd.add_option("--overlay", path,
                 "a second volume (e.g. PET) fused into dvr frames in patient space, on its "
                 "own grid (mip: its maximum along each ray over the grey); warns when the two "
                 "name no common Frame of Reference");
  cmd.add_option("--overlay-tf", tf,
                 "the overlay's table: a preset name or a preset JSON file, over the overlay's "
                 "values (default: --overlay-window and --overlay-colormap)");
  cmd.add_option("--overlay-window", window,
                 "LO,HI: transparent at LO, opaque up to --overlay-opacity at HI, in SUV for "
                 "PET with an SUV scale, else its values (default: its DICOM window, else its "
                 "value range)");
  cmd.add_option("--overlay-colormap", colormap, "hot-iron (default), rainbow or grey")
      ->check(CLI::IsMember({"hot-iron", "rainbow", "grey"}));
  cmd.add_option("--overlay-opacity", opacity,
                 "with a window: the opacity per reference step at HI (default 0.5); with "
                 "--overlay-tf: a factor on the table's opacities (default 1)")
      ->check(CLI::Range(0.0, 1.0));
  cmd.add_option("--overlay-time", time,
                 "a 4D overlay's time point, 0-based (default: the study's --time when both "
                 "have as many time points, as the workstation's overlay follows its time "
                 "slider; else the first)")
      ->check(CLI::NonNegativeNumber);
}

std::optional<std::pair<Volume, TransferFunction>> OverlayOption::load(const Volume& study) const {
  if (path.empty()) return std::nullopt;
  Volume o;
  try {
    LoadOptions options;
    options.timePoint = time;
    o = loadVolume(path, options);
    // Following the study: the same index when both are 4D with the same count.
    if (!time && study.timePoints > 1 && o.timePoints == study.timePoints &&
        study.timePoint != o.timePoint) {
      options.timePoint = study.timePoint;
      o = loadVolume(path, options);
    }
  } catch (const Error& e) {
    throw Error(e.kind(), (time ? "--overlay-time " + std::to_string(*time) + ", " : "") +
                              "--overlay " + path + ": " + e.what());
  }
  if (!tf.empty()) {
    TransferFunction table;
    if (std::filesystem::is_regular_file(tf)) {
      std::ifstream in(tf);
      std::stringstream text;
      text << in.rdbuf();
      table = parsePreset(text.str(), tf).tf;
    } else {
      table = findPreset(tf).tf;
    }
    if (table.points.empty())
      throw inputError("--overlay-tf " + tf + ": it has no colour table (an iso or mip preset?)");
    return std::make_pair(std::move(o), scaledOpacity(table, opacity.value_or(1.0)));
  }
  double lo = 0.0, hi = 0.0;
  const double toPhysical = o.suv && o.suv->factor > 0.0 ? 1.0 / o.suv->factor : 1.0;
  if (!window.empty()) {
    std::tie(lo, hi) = parseWindow(window);
    lo *= toPhysical, hi *= toPhysical;
  } else if (o.window && o.window->width > 0.0) {
    lo = o.window->level - 0.5 * o.window->width;
    hi = o.window->level + 0.5 * o.window->width;
  } else {
    const ValueRange r = storedRange(o);
    lo = o.toPhysical(r.min);
    hi = o.toPhysical(r.max);
    if (!(hi > lo)) hi = lo + 1.0;  // a constant overlay: all of it at the window's top
  }
  TransferFunction table = overlayWindowTable(lo, hi, colormap, opacity.value_or(0.5));
  return std::make_pair(std::move(o), std::move(table));
}

}  // namespace voxray::cli
