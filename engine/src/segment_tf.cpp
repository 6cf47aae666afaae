#include "segment_tf.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "label_cells.h"
#include "segment_table.h"  // kernels/: the layout
#include "voxray/engine/volume_property.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

std::array<int, 256> segmentTfSlots(const std::vector<Segment>& segments, const RenderParams& p) {
  std::array<int, 256> slots{};
  if (p.mode != Mode::Dvr || !p.tf2d.empty() || p.segmentTfs.empty()) return slots;
  std::array<bool, 256> own{};
  for (const Segment& s : segments)
    if (s.label != 0 && s.visible && p.segmentTfs.count(s.label)) own[s.label] = true;
  int next = 0;
  for (int l = 1; l < 256; ++l)
    if (own[size_t(l)]) slots[size_t(l)] = ++next;
  return slots;
}

bool anySegmentTf(const std::array<int, 256>& slots) {
  return std::any_of(slots.begin(), slots.end(), [](int s) { return s > 0; });
}

std::vector<Lut> bakeSegmentTfs(const std::array<int, 256>& slots, const RenderParams& p,
                                const Volume& v, const Lut& volumeLut) {
  std::vector<Lut> out(size_t(*std::max_element(slots.begin(), slots.end())));
  for (int l = 1; l < 256; ++l) {
    const int s = slots[size_t(l)];
    if (s == 0) continue;
    TransferFunction tf{p.segmentTfs.at(l)};
    Lut& lut = out[size_t(s - 1)];
    lut.storedMin = volumeLut.storedMin;
    lut.scale = volumeLut.scale;
    lut.rgba.resize(volumeLut.rgba.size());
    // bakeLut's entries, at the volume table's stored values.
    for (size_t k = 0; k < lut.rgba.size(); ++k) {
      const double stored = lut.storedMin + double(k) / lut.scale;
      lut.rgba[k] = glm::vec4(glm::clamp(tf.evaluate(v.toPhysical(stored)), 0.0, 1.0));
    }
  }
  return out;
}

std::vector<glm::vec4> packSegmentTfs(const std::vector<Lut>& luts) {
  std::vector<glm::vec4> out;
  for (const Lut& l : luts) out.insert(out.end(), l.rgba.begin(), l.rgba.end());
  return out;
}

std::vector<uint8_t> segmentTfCells(const LabelCells& cells, const std::vector<int16_t>& minMax,
                                    const std::array<int, 256>& slots, const std::vector<Lut>& luts,
                                    const std::vector<glm::vec4>& table) {
  if (luts.empty() || cells.present.size() * 2 != minMax.size()) return {};
  // Per table, how many entries below k have an opacity above 0 (classify.cl's opaque_before).
  std::vector<std::vector<int>> before(luts.size());
  for (size_t s = 0; s < luts.size(); ++s) {
    before[s].assign(luts[s].rgba.size() + 1, 0);
    for (size_t k = 0; k < luts[s].rgba.size(); ++k)
      before[s][k + 1] = before[s][k] + (luts[s].rgba[k].a > 0.0f);
  }
  std::vector<int> owners;  // the labels whose own table may show
  for (int l = 1; l < 256; ++l)
    if (slots[size_t(l)] > 0 && table[size_t(2 * l + 1)].x > 0.0f &&
        before[size_t(slots[size_t(l)] - 1)].back() > 0)
      owners.push_back(l);
  std::vector<uint8_t> out(cells.present.size(), 0);
  if (owners.empty()) return out;
  const Lut& any = luts.front();  // every table has the volume table's mapping
  const int last = int(any.rgba.size()) - 1;
  for (size_t c = 0; c < out.size(); ++c) {
    const auto& bits = cells.present[c];
    // classify.cl's dvr test, with its margins, on each owner's table.
    const float lo = float(minMax[2 * c]) - 0.5f, hi = float(minMax[2 * c + 1]) + 0.5f;
    const float x0 = std::clamp(float((lo - any.storedMin) * any.scale), 0.0f, float(last));
    const float x1 = std::clamp(float((hi - any.storedMin) * any.scale), 0.0f, float(last));
    const int a = std::max(int(std::floor(x0)) - 1, 0);
    const int b = std::min(int(std::floor(x1)) + 2, last);
    for (int l : owners) {
      if (!(bits[size_t(l >> 6)] >> (l & 63) & 1u)) continue;
      const auto& o = before[size_t(slots[size_t(l)] - 1)];
      if (o[size_t(b + 1)] - o[size_t(a)] > 0) {
        out[c] = 1;
        break;
      }
    }
  }
  return out;
}

namespace {

Error segmentTfError(const std::string& why, const std::string& item) {
  return inputError("--segment-tf: " + why + ", got '" + item +
                    "' (L:SPEC;L:SPEC..., L a segment's label 1 ... 255, SPEC a preset name, a "
                    ".json or .vp transfer-function file, or points HU:R:G:B:A,...)");
}

bool looksLikePoints(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) {
    return std::isdigit(c) || c == '.' || c == '-' || c == '+' || c == ':' || c == ',' ||
           c == 'e' || c == 'E';
  });
}

bool endsWith(const std::string& s, const std::string& tail) {
  if (s.size() < tail.size()) return false;
  std::string end = s.substr(s.size() - tail.size());
  std::transform(end.begin(), end.end(), end.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return end == tail;
}

}  // namespace

std::map<int, std::vector<ControlPoint>> parseSegmentTfs(const std::string& text) {
  std::map<int, std::vector<ControlPoint>> out;
  if (text.empty() || text == "off") return out;
  if (std::any_of(text.begin(), text.end(), [](unsigned char c) { return c < 0x20 || c == 0x7F; }))
    throw segmentTfError("it is one line of printable text", text);
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(';', start), text.size());
    const std::string item = text.substr(start, end - start);
    start = end + 1;
    const size_t colon = item.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == item.size())
      throw segmentTfError("each item is L:SPEC", item);
    const std::string labelText = item.substr(0, colon), spec = item.substr(colon + 1);
    size_t used = 0;
    int label = -1;
    try {
      label = std::stoi(labelText, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != labelText.size() || label < 1 || label > 255)
      throw segmentTfError("'" + labelText + "' is not a label 1 ... 255", item);
    if (out.count(label)) throw segmentTfError("label " + labelText + " comes twice", item);
    std::vector<ControlPoint> points;
    if (looksLikePoints(spec)) {
      points = parseTfPoints(spec);  // --tf's parser and its messages
    } else if (endsWith(spec, ".json") || endsWith(spec, ".vp")) {
      points = renderTable(readVolumePropertyFile(spec));
    } else {
      const Preset& preset = findPreset(spec);
      if (preset.tf.points.empty())
        throw segmentTfError("preset " + preset.name + " has no transfer function", item);
      points = preset.tf.points;
    }
    if (points.empty()) throw segmentTfError("a table needs at least one point", item);
    if (points.size() > kMaxTfPoints)
      throw segmentTfError("a table has at most " + std::to_string(kMaxTfPoints) + " points", item);
    out[label] = std::move(points);
    if (end == text.size()) break;
  }
  return out;
}

std::string formatSegmentTfs(const std::map<int, std::vector<ControlPoint>>& tfs) {
  std::string out;
  for (const auto& [label, points] : tfs) {
    if (!out.empty()) out += ';';
    out += std::to_string(label);
    out += ':';
    out += formatTfPoints(points);
  }
  return out;
}

}  // namespace voxray
