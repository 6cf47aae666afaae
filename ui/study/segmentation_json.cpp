#include "segmentation_json.h"

#include <algorithm>
#include <cmath>

#include "label_map_text.h"
#include "voxray/io/error.h"
#include "voxray/io/segmentation_check.h"

namespace voxray {
namespace {

using Json = nlohmann::ordered_json;

[[noreturn]] void wrong(const std::string& field, const std::string& what) {
  throw inputError(field + " " + what);
}

const Json& member(const Json& obj, const std::string& key, const std::string& field) {
  if (!obj.is_object() || !obj.contains(key)) wrong(field, "is missing");
  return obj.at(key);
}

std::vector<double> numbers(const Json& v, size_t count, const std::string& field) {
  if (!v.is_array() || v.size() != count)
    wrong(field, "must be an array of " + std::to_string(count) + " numbers");
  std::vector<double> out;
  for (const Json& n : v) {
    if (!n.is_number() || !std::isfinite(n.get<double>()))
      wrong(field, "must be an array of " + std::to_string(count) + " numbers");
    out.push_back(n.get<double>());
  }
  return out;
}

std::string text(const Json& v, const std::string& field) {
  if (!v.is_string()) wrong(field, "must be a string");
  return v.get<std::string>();
}

Json codeJson(const Segment::Code& c) {
  return {{"value", c.value}, {"scheme", c.scheme}, {"meaning", c.meaning}};
}

Segment::Code codeFrom(const Json& j, const std::string& field) {
  return {text(member(j, "value", field + ".value"), field + ".value"),
          text(member(j, "scheme", field + ".scheme"), field + ".scheme"),
          text(member(j, "meaning", field + ".meaning"), field + ".meaning")};
}

}  // namespace

std::string display3dName(Segment::Display3d d) {
  switch (d) {
    case Segment::Display3d::Surface:
      return "surface";
    case Segment::Display3d::Hidden:
      return "hidden";
    case Segment::Display3d::Volume:
      break;
  }
  return "volume";
}

std::optional<Segment::Display3d> parseDisplay3d(const std::string& name) {
  for (auto d :
       {Segment::Display3d::Volume, Segment::Display3d::Surface, Segment::Display3d::Hidden})
    if (display3dName(d) == name) return d;
  return std::nullopt;
}

nlohmann::ordered_json segmentationToJson(const Segmentation& s) {
  const auto& g = s.grid;
  Json j;
  j["dims"] = {g.dims.x, g.dims.y, g.dims.z};
  j["spacing-mm"] = {g.spacingMm.x, g.spacingMm.y, g.spacingMm.z};
  j["origin-mm"] = {g.originMm.x, g.originMm.y, g.originMm.z};
  j["direction"] = Json::array();
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) j["direction"].push_back(g.direction[c][r]);
  j["segments"] = Json::array();
  for (const auto& seg : s.segments)
    j["segments"].push_back({{"label", seg.label},
                             {"name", seg.name},
                             {"colour", {seg.colour.r, seg.colour.g, seg.colour.b}},
                             {"opacity", seg.opacity},
                             {"visible", seg.visible},
                             {"display-3d", display3dName(seg.display3d)},
                             {"category", codeJson(seg.category)},
                             {"type", codeJson(seg.type)}});
  j["label-map"] = {{"encoding", "zlib+base64"}, {"text", labelMapToText(s.labels)}};
  return j;
}

Segmentation segmentationFromJson(const nlohmann::ordered_json& j) {
  if (!j.is_object()) wrong("segmentation", "must be an object { ... }");
  Segmentation s;
  const auto dims = numbers(member(j, "dims", "dims"), 3, "dims");
  for (int a = 0; a < 3; ++a) {
    if (dims[size_t(a)] < 1 || dims[size_t(a)] > 65536 ||
        dims[size_t(a)] != std::floor(dims[size_t(a)]))
      wrong("dims", "must be 3 whole numbers from 1 to 65536");
    s.grid.dims[a] = int(dims[size_t(a)]);
  }
  if (s.grid.voxelCount() > (size_t(1) << 34))
    wrong("dims", "describe more voxels than any volume");
  const auto spacing = numbers(member(j, "spacing-mm", "spacing-mm"), 3, "spacing-mm");
  const auto origin = numbers(member(j, "origin-mm", "origin-mm"), 3, "origin-mm");
  const auto direction = numbers(member(j, "direction", "direction"), 9, "direction");
  for (int a = 0; a < 3; ++a) {
    if (!(spacing[size_t(a)] > 0.0)) wrong("spacing-mm", "must be 3 numbers above 0");
    s.grid.spacingMm[a] = spacing[size_t(a)];
    s.grid.originMm[a] = origin[size_t(a)];
    for (int r = 0; r < 3; ++r) s.grid.direction[a][r] = direction[size_t(a * 3 + r)];
  }
  const Json& segments = member(j, "segments", "segments");
  if (!segments.is_array() || segments.size() > 255)
    wrong("segments", "must be an array of at most 255 segments");
  for (size_t i = 0; i < segments.size(); ++i) {
    const std::string f = "segments[" + std::to_string(i) + "]";
    const Json& e = segments[i];
    Segment seg;
    const Json& label = member(e, "label", f + ".label");
    if (!label.is_number_integer() || label.get<long long>() < 1 || label.get<long long>() > 255)
      wrong(f + ".label", "must be a whole number from 1 to 255");
    seg.label = uint8_t(label.get<int>());
    seg.name = text(member(e, "name", f + ".name"), f + ".name");
    const auto c = numbers(member(e, "colour", f + ".colour"), 3, f + ".colour");
    seg.colour = glm::clamp(glm::vec3(float(c[0]), float(c[1]), float(c[2])), 0.0f, 1.0f);
    const auto o = numbers(Json::array({member(e, "opacity", f + ".opacity")}), 1, f + ".opacity");
    seg.opacity = std::clamp(float(o[0]), 0.0f, 1.0f);
    const Json& visible = member(e, "visible", f + ".visible");
    if (!visible.is_boolean()) wrong(f + ".visible", "must be true or false");
    seg.visible = visible.get<bool>();
    if (e.contains("display-3d")) {  // optional: older sessions show every segment in the volume
      const auto d = parseDisplay3d(text(e.at("display-3d"), f + ".display-3d"));
      if (!d) wrong(f + ".display-3d", "must be volume, surface or hidden");
      seg.display3d = *d;
    }
    seg.category = codeFrom(member(e, "category", f + ".category"), f + ".category");
    seg.type = codeFrom(member(e, "type", f + ".type"), f + ".type");
    s.segments.push_back(seg);
  }
  const Json& map = member(j, "label-map", "label-map");
  if (text(member(map, "encoding", "label-map.encoding"), "label-map.encoding") != "zlib+base64")
    wrong("label-map.encoding", "must be \"zlib+base64\"");
  s.labels = labelMapFromText(text(member(map, "text", "label-map.text"), "label-map.text"),
                              s.grid.voxelCount(), "label-map.text");
  checkSegmentation(s);
  return s;
}

}  // namespace voxray
