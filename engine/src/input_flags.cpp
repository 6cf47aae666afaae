#include "voxray/engine/input_flags.h"

#include <algorithm>

#include "text_parse.h"
#include "voxray/io/error.h"
#include "voxray/io/orientation.h"

namespace voxray {
using namespace text;

namespace {

using O = LoadOptions;
using S = const std::string&;

// A raw flag's layout: created by the first raw flag read.
RawLayout& raw(LoadOptions& o) {
  if (!o.raw) o.raw.emplace();
  return *o.raw;
}

// A raw flag's text, or "" when the options read no raw data.
template <class Format>
std::function<std::string(const O&)> rawText(Format format) {
  return [format](const O& o) { return o.raw ? format(*o.raw) : std::string(); };
}

std::vector<EnumLabel> sampleTypeLabels() {
  std::vector<EnumLabel> out;
  for (SampleType t : {SampleType::U8, SampleType::I16, SampleType::U16, SampleType::F32})
    out.push_back({toString(t), toString(t), {}});
  return out;
}

// In ByteOrder's order (parseByteOrder also reads "le" and "be").
const std::vector<EnumLabel> kByteOrderLabels = {{"little", "little", {}}, {"big", "big", {}}};

void parseRange(RawLayout& l, const std::string& s) {
  auto dash = s.find('-', 1);
  if (dash == std::string::npos)
    throw inputError("--raw-range: expected FIRST-LAST, e.g. 1-113, got '" + s + "'");
  l.range =
      std::make_pair(toInt("raw-range", s.substr(0, dash)), toInt("raw-range", s.substr(dash + 1)));
}

std::vector<InputFlagSpec> makeInputFlagSpecs() {
  const ParamDomain dims = ParamDomain().atLeast(1).steps(1, 0);
  // Any positive spacing is accepted; a control offers up to 10 cm.
  const ParamDomain spacing = ParamDomain().above(0).steps(0.1, 3).in("mm").offer({}, 100);
  const ParamDomain offset = ParamDomain().atLeast(0).steps(1, 0).in("bytes");
  const std::vector<EnumLabel> types = sampleTypeLabels();
  const ParamDomain timePoint = ParamDomain().atLeast(0).steps(1, 0);
  return {
      {"raw-dims", "X,Y[,Z]", "raw: voxels along x, y and z (Z: the number of slice files)", dims,
       [dims](O& o, S s) {
         auto d = toInts("raw-dims", s, 2, 3);
         for (int n : d) checkInDomain("raw-dims", dims, n, s);
         raw(o).dims = {d[0], d[1], d.size() > 2 ? d[2] : 0};
       },
       rawText([](const RawLayout& l) {
         return std::to_string(l.dims.x) + "," + std::to_string(l.dims.y) +
                (l.dims.z ? "," + std::to_string(l.dims.z) : "");
       })},
      {"raw-type", labelNames(types, "|"), "raw: sample type (default i16)",
       ParamDomain().choices(types), [](O& o, S s) { raw(o).type = parseSampleType(s); },
       rawText([](const RawLayout& l) { return std::string(toString(l.type)); })},
      {"raw-endian", labelNames(kByteOrderLabels, "|"), "raw: byte order (default little)",
       ParamDomain().choices(kByteOrderLabels), [](O& o, S s) { raw(o).order = parseByteOrder(s); },
       rawText([](const RawLayout& l) { return kByteOrderLabels[size_t(l.order)].name; })},
      {"raw-spacing", "SX,SY,SZ", "raw: voxel spacing in mm (default 1,1,1)", spacing,
       [spacing](O& o, S s) {
         glm::dvec3 v = toVec3("raw-spacing", s);
         for (int a = 0; a < 3; ++a) checkInDomain("raw-spacing", spacing, v[a], s);
         raw(o).spacingMm = v;
       },
       rawText([](const RawLayout& l) { return fmt(l.spacingMm); })},
      {"raw-offset", "BYTES", "raw: header bytes to skip in each file", offset,
       [offset](O& o, S s) {
         raw(o).headerBytes =
             size_t(checkInDomain("raw-offset", offset, toInt("raw-offset", s), s));
       },
       rawText([](const RawLayout& l) { return std::to_string(l.headerBytes); })},
      {"raw-rescale",
       "SLOPE,INTERCEPT",
       "raw: to HU, hu = raw * SLOPE + INTERCEPT",
       {},
       [](O& o, S s) {
         auto r = toDoubles("raw-rescale", s, 2, 2);
         raw(o).slope = r[0];
         raw(o).intercept = r[1];
       },
       rawText([](const RawLayout& l) { return fmt(l.slope) + "," + fmt(l.intercept); })},
      {"raw-range",
       "FIRST-LAST",
       "raw: slice numbers of a pattern or folder",
       {},
       [](O& o, S s) { parseRange(raw(o), s); },
       rawText([](const RawLayout& l) {
         return l.range ? std::to_string(l.range->first) + "-" + std::to_string(l.range->second)
                        : std::string();
       })},
      {"raw-axes",
       "CODE",
       "raw: patient direction of the x, y, z index axes, e.g. LPI when slice 1 is the top of "
       "the head (default LPS)",
       {},
       [](O& o, S s) { raw(o).direction = directionFromAxesCode(s); },
       rawText([](const RawLayout& l) { return axesCodeFromDirection(l.direction); })},
      {"series",
       "SERIES",
       "DICOM: series number or UID (default: the largest volume)",
       {},
       [](O& o, S s) { o.series = s; },
       [](const O& o) { return o.series; }},
      {"time", "K",
       "4D (DICOM, NIfTI): the time point (phase) to open, 0-based (default 0, or the one "
       "--series names)",
       timePoint,
       [timePoint](O& o, S s) {
         if (s.empty()) {  // what format writes for none
           o.timePoint.reset();
           return;
         }
         o.timePoint = int(checkInDomain("time", timePoint, toInt("time", s), s));
       },
       [](const O& o) { return o.timePoint ? std::to_string(*o.timePoint) : std::string(); }},
  };
}

}  // namespace

const std::vector<InputFlagSpec>& inputFlagSpecs() {
  static const std::vector<InputFlagSpec> specs = makeInputFlagSpecs();
  return specs;
}

const InputFlagSpec& findInputFlagSpec(const std::string& key) {
  const auto& specs = inputFlagSpecs();
  auto it = std::find_if(specs.begin(), specs.end(),
                         [&](const InputFlagSpec& s) { return s.key == key; });
  if (it == specs.end()) throw inputError("input flags: unknown flag --" + key);
  return *it;
}

LoadOptions loadOptionsFromFlags(const std::map<std::string, std::string>& given) {
  LoadOptions o;
  for (const auto& [key, value] : given) findInputFlagSpec(key).parse(o, value);
  if (o.raw && !given.count("raw-dims"))
    throw inputError("raw flags need --raw-dims X,Y[,Z] to read INPUT as raw data");
  return o;
}

std::map<std::string, std::string> flagsFromLoadOptions(const LoadOptions& o) {
  std::map<std::string, std::string> flags;
  for (const auto& spec : inputFlagSpecs())
    if (std::string text = spec.format(o); !text.empty()) flags.emplace(spec.key, text);
  return flags;
}

}  // namespace voxray
