#include "input_options.h"

#include <sstream>

#include "progress.h"
#include "voxray/io/error.h"
#include "voxray/io/orientation.h"
#include "voxray/io/phantom.h"

namespace voxray::cli {

namespace {

std::vector<double> numbers(const std::string& flag, const std::string& s, size_t n) {
  std::vector<double> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      size_t used = 0;
      out.push_back(std::stod(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw inputError(flag + ": '" + item + "' is not a number");
    }
  }
  if (out.size() != n && !(flag == "--raw-dims" && out.size() == 2))
    throw inputError(flag + ": expected " + std::to_string(n) + " comma-separated numbers, got '" +
                     s + "'");
  return out;
}

}  // namespace

void InputOptions::add(CLI::App& cmd) {
  cmd.add_option("input", input,
                 "DICOM file or folder, raw slice folder, printf pattern or raw file "
                 "(none: the embedded head phantom)");
  cmd.add_option("--raw-dims", rawDims, "raw: X,Y[,Z] voxels (Z: number of slice files)");
  cmd.add_option("--raw-type", rawType, "raw: u8, i16, u16 or f32")->default_str("i16");
  cmd.add_option("--raw-endian", rawEndian, "raw: big or little")->default_str("little");
  cmd.add_option("--raw-spacing", rawSpacing, "raw: SX,SY,SZ in mm");
  cmd.add_option("--raw-offset", rawOffset, "raw: header bytes to skip in each file");
  cmd.add_option("--raw-rescale", rawRescale, "raw: SLOPE,INTERCEPT to HU");
  cmd.add_option("--raw-range", rawRange, "raw: FIRST-LAST slice numbers");
  cmd.add_option("--raw-axes", rawAxes,
                 "raw: patient direction of the x, y, z index axes, e.g. LPI when slice 1 is "
                 "the top of the head (default LPS)");
  cmd.add_option("--series", series, "DICOM: series number or UID (default: the largest volume)");
  cmd.add_option("--phantom-size", phantomSize,
                 "no INPUT: voxels per axis of the head phantom (1024: a 2 GiB volume)")
      ->check(CLI::Range(2, 1024));
}

LoadOptions InputOptions::loadOptions() const {
  LoadOptions o;
  o.series = series;
  if (!rawDims.empty()) {
    RawLayout l;
    auto d = numbers("--raw-dims", rawDims, 3);
    l.dims = {int(d[0]), int(d[1]), d.size() > 2 ? int(d[2]) : 0};
    l.type = parseSampleType(rawType);
    l.order = parseByteOrder(rawEndian);
    if (!rawSpacing.empty()) {
      auto s = numbers("--raw-spacing", rawSpacing, 3);
      l.spacingMm = {s[0], s[1], s[2]};
    }
    l.headerBytes = rawOffset;
    if (!rawRescale.empty()) {
      auto r = numbers("--raw-rescale", rawRescale, 2);
      l.slope = r[0];
      l.intercept = r[1];
    }
    if (!rawRange.empty()) {
      auto dash = rawRange.find('-', 1);
      if (dash == std::string::npos)
        throw inputError("--raw-range: expected FIRST-LAST, e.g. 1-113, got '" + rawRange + "'");
      try {
        l.range = std::make_pair(std::stoi(rawRange.substr(0, dash)),
                                 std::stoi(rawRange.substr(dash + 1)));
      } catch (const std::exception&) {
        throw inputError("--raw-range: expected FIRST-LAST, e.g. 1-113, got '" + rawRange + "'");
      }
    }
    if (!rawAxes.empty()) l.direction = directionFromAxesCode(rawAxes);
    o.raw = l;
  } else if (!rawSpacing.empty() || !rawRescale.empty() || !rawRange.empty() || rawOffset ||
             !rawAxes.empty()) {
    throw inputError("raw flags need --raw-dims X,Y[,Z] to read INPUT as raw data");
  }
  return o;
}

Volume InputOptions::load() const {
  LoadOptions o = loadOptions();
  if (input.empty()) return makeHeadPhantom(phantomSize);
  o.progress = terminalProgress("loading");
  return loadVolume(input, o);
}

}  // namespace voxray::cli
