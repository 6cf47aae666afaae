// The two file forms of a VolumeProperty: Voxray's JSON and 3D Slicer's .vp text.
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "voxray/engine/volume_property.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

constexpr const char* kFormat = "voxray-transfer-function";
constexpr int kVersion = 1;

using Json = nlohmann::json;

// Shortest text that reads back as the same double, so a round trip is exact.
std::string exact(double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// A count as the file has it: a whole number as such ("500000", not "5e+05").
std::string countText(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e15) return std::to_string((long long)v);
  return exact(v);
}

// J's KEY as text, FALLBACK when absent; a value that is not text is refused naming the field
// (nlohmann's value() would throw its own type error, which no caller expects).
std::string textField(const Json& j, const char* key, const char* fallback,
                      const std::string& origin) {
  auto it = j.find(key);
  if (it == j.end()) return fallback;
  if (!it->is_string()) throw inputError(origin + ": " + key + " must be text");
  return it->get<std::string>();
}

double number(const Json& j, const std::string& origin, const std::string& field) {
  if (!j.is_number()) throw inputError(origin + ": " + field + " must be a number");
  return j.get<double>();
}

// [[x, v...], ...] with WIDTH numbers per point.
std::vector<std::vector<double>> pointList(const Json& j, const std::string& origin,
                                           const std::string& field, size_t width) {
  if (!j.is_array()) throw inputError(origin + ": " + field + " must be a list of points");
  if (j.size() > kMaxTfPoints)
    throw inputError(origin + ": " + field + " has " + std::to_string(j.size()) +
                     " points; at most " + std::to_string(kMaxTfPoints) + " are read");
  std::vector<std::vector<double>> out;
  for (size_t i = 0; i < j.size(); ++i) {
    const Json& p = j[i];
    std::string where = field + " point " + std::to_string(i + 1);
    if (!p.is_array() || p.size() != width)
      throw inputError(origin + ": " + where + " must be a list of " + std::to_string(width) +
                       " numbers");
    std::vector<double> v;
    for (const Json& x : p) v.push_back(number(x, origin, where));
    out.push_back(std::move(v));
  }
  return out;
}

std::vector<OpacityNode> opacityNodes(const std::vector<std::vector<double>>& rows) {
  std::vector<OpacityNode> out;
  for (const auto& r : rows) out.push_back({r[0], r[1]});
  return out;
}

Json opacityJson(const std::vector<OpacityNode>& nodes) {
  Json out = Json::array();
  for (const auto& n : nodes) out.push_back({n.x, n.opacity});
  return out;
}

// Whitespace-separated numbers of a .vp file, read one at a time with what each one is.
class Numbers {
 public:
  Numbers(const std::string& text, std::string origin) : in_(text), origin_(std::move(origin)) {}
  double next(const std::string& field) {
    std::string token;
    if (!(in_ >> token))
      throw inputError(origin_ + ": the file ends before the " + field +
                       "; a Slicer volume property has six numbers, then the scalar opacity, "
                       "gradient opacity and colour functions");
    double v = 0.0;
    auto r = std::from_chars(token.data(), token.data() + token.size(), v);
    if (r.ec != std::errc() || r.ptr != token.data() + token.size())
      throw inputError(origin_ + ": the " + field + " is '" + token + "', not a number");
    return v;
  }
  // A function: the count of numbers, then the numbers, WIDTH per point.
  std::vector<std::vector<double>> function(const std::string& field, size_t width) {
    double count = next(field + "'s count");
    if (!(count >= 0.0) || count != std::floor(count) || std::fmod(count, double(width)) != 0.0)
      throw inputError(origin_ + ": the " + field + " count is " + countText(count) +
                       "; it counts the numbers that follow, " + std::to_string(width) +
                       " per point");
    if (count > double(width * kMaxTfPoints))
      throw inputError(origin_ + ": the " + field + " has " +
                       countText(std::floor(count / double(width))) + " points; at most " +
                       std::to_string(kMaxTfPoints) + " are read");
    std::vector<std::vector<double>> out(size_t(count) / width);
    for (size_t i = 0; i < out.size(); ++i)
      for (size_t k = 0; k < width; ++k)
        out[i].push_back(next(field + " point " + std::to_string(i + 1)));
    return out;
  }

 private:
  std::istringstream in_;
  std::string origin_;
};

// ".json", ".vp": how the two file forms are told apart, whatever the case.
std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string vpFunction(const std::vector<std::vector<double>>& rows, size_t width) {
  std::string out = std::to_string(rows.size() * width);
  for (const auto& r : rows)
    for (double v : r) out += " " + exact(v);
  return out + "\n";
}

// The "tf2d" section (its own version, so it can grow without the file's): the gradient axis'
// top and the primitives, each {"shape": "rect"|"tri", "hu": [HU0, HU1], "gradient": [G0, G1],
// "color": [R, G, B], "opacity": A, "soft": S}.
constexpr int kTf2dVersion = 1;

Tf2d tf2dOf(const Json& j, const std::string& origin) {
  if (!j.is_object()) throw inputError(origin + ": tf2d must be an object");
  if (!j.contains("version") || !j["version"].is_number_integer() ||
      j["version"].get<int>() != kTf2dVersion)
    throw inputError(origin + ": tf2d.version must be " + std::to_string(kTf2dVersion) +
                     " (a newer Voxray may have written another)");
  Tf2d tf;
  if (j.contains("gradientMax"))
    tf.gradientMax = number(j["gradientMax"], origin, "tf2d.gradientMax");
  const Json& list = j.contains("primitives") ? j["primitives"] : Json();
  if (!list.is_array()) throw inputError(origin + ": tf2d.primitives must be a list");
  if (list.size() > kMaxTf2dPrimitives)
    throw inputError(origin + ": tf2d.primitives has " + std::to_string(list.size()) +
                     " entries; at most " + std::to_string(kMaxTf2dPrimitives) + " are read");
  for (size_t i = 0; i < list.size(); ++i) {
    const Json& e = list[i];
    std::string at = "tf2d.primitives[" + std::to_string(i) + "]";
    if (!e.is_object()) throw inputError(origin + ": " + at + " must be an object");
    Tf2dPrimitive p;
    std::string shape = textField(e, "shape", "", origin);
    if (shape != "rect" && shape != "tri")
      throw inputError(origin + ": " + at + ".shape is '" + shape + "'; it must be rect or tri");
    p.shape = shape == "tri" ? Tf2dShape::Triangle : Tf2dShape::Rectangle;
    auto numbers = [&](const char* key, size_t n) {
      std::string field = at + "." + key;
      if (!e.contains(key) || !e[key].is_array() || e[key].size() != n)
        throw inputError(origin + ": " + field + " must be a list of " + std::to_string(n) +
                         " numbers");
      std::vector<double> v;
      for (const Json& x : e[key]) v.push_back(number(x, origin, field));
      return v;
    };
    std::vector<double> hu = numbers("hu", 2), g = numbers("gradient", 2),
                        rgb = numbers("color", 3);
    p.hu0 = hu[0], p.hu1 = hu[1], p.g0 = g[0], p.g1 = g[1];
    p.rgb = {rgb[0], rgb[1], rgb[2]};
    if (!e.contains("opacity")) throw inputError(origin + ": " + at + ".opacity is missing");
    p.opacity = number(e["opacity"], origin, at + ".opacity");
    if (e.contains("soft")) p.soft = number(e["soft"], origin, at + ".soft");
    tf.primitives.push_back(p);
  }
  validate(tf, origin);
  return tf;
}

Json tf2dJson(const Tf2d& tf) {
  Json list = Json::array();
  for (const Tf2dPrimitive& p : tf.primitives)
    list.push_back({{"shape", p.shape == Tf2dShape::Triangle ? "tri" : "rect"},
                    {"hu", {p.hu0, p.hu1}},
                    {"gradient", {p.g0, p.g1}},
                    {"color", {p.rgb.r, p.rgb.g, p.rgb.b}},
                    {"opacity", p.opacity},
                    {"soft", p.soft}});
  return {{"version", kTf2dVersion}, {"gradientMax", tf.gradientMax}, {"primitives", list}};
}

}  // namespace

VolumeProperty parseVolumePropertyJson(const std::string& text, const std::string& origin) {
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::exception& e) {
    throw inputError(origin + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  if (!j.is_object() || !j.contains("format") || !j["format"].is_string() ||
      j["format"].get<std::string>() != kFormat)
    throw inputError(origin + ": not a Voxray transfer function (its \"format\" must be \"" +
                     kFormat + "\")");
  if (!j.contains("version") || !j["version"].is_number_integer() ||
      j["version"].get<int>() > kVersion)
    throw inputError(origin + ": version " + j.value("version", Json()).dump() +
                     " is not one this Voxray reads (it reads version " + std::to_string(kVersion) +
                     "); a newer Voxray wrote it");
  VolumeProperty vp;
  if (j.contains("name")) {
    if (!j["name"].is_string()) throw inputError(origin + ": name must be text");
    vp.name = j["name"].get<std::string>();
  }
  std::string curve = textField(j, "curve", "linear", origin);
  if (curve != "linear" && curve != "smooth")
    throw inputError(origin + ": curve is '" + curve + "'; it must be linear or smooth");
  vp.curve = curve == "smooth" ? TfCurve::Smooth : TfCurve::Linear;
  for (const auto& r : pointList(j.value("color", Json()), origin, "colour", 4))
    vp.color.push_back({r[0], {r[1], r[2], r[3]}});
  vp.opacity = opacityNodes(pointList(j.value("opacity", Json()), origin, "opacity", 2));
  if (j.contains("gradientOpacity"))
    vp.gradientOpacity =
        opacityNodes(pointList(j["gradientOpacity"], origin, "gradient opacity", 2));
  if (j.contains("tf2d")) vp.tf2d = tf2dOf(j["tf2d"], origin);
  if (j.contains("unitDistanceMm"))
    vp.unitDistanceMm = number(j["unitDistanceMm"], origin, "unitDistanceMm");
  std::string interpolation = textField(j, "interpolation", "linear", origin);
  if (interpolation != "linear" && interpolation != "nearest")
    throw inputError(origin + ": interpolation is '" + interpolation +
                     "'; it must be linear or nearest");
  vp.nearest = interpolation == "nearest";
  if (j.contains("shading")) {
    const Json& s = j["shading"];
    if (!s.is_object()) throw inputError(origin + ": shading must be an object");
    if (s.contains("enabled")) {
      if (!s["enabled"].is_boolean())
        throw inputError(origin + ": shading.enabled must be true or false");
      vp.shade = s["enabled"].get<bool>();
    }
    const std::pair<const char*, double*> fields[] = {{"ambient", &vp.ambient},
                                                      {"diffuse", &vp.diffuse},
                                                      {"specular", &vp.specular},
                                                      {"specularPower", &vp.specularPower}};
    for (const auto& [key, field] : fields)
      if (s.contains(key)) *field = number(s[key], origin, std::string("shading.") + key);
  }
  validate(vp, origin);
  return vp;
}

std::string toVolumePropertyJson(const VolumeProperty& vp) {
  Json j;
  j["format"] = kFormat;
  j["version"] = kVersion;
  j["name"] = vp.name;
  j["curve"] = vp.curve == TfCurve::Smooth ? "smooth" : "linear";
  j["unitDistanceMm"] = vp.unitDistanceMm;
  j["interpolation"] = vp.nearest ? "nearest" : "linear";
  Json color = Json::array();
  for (const auto& n : vp.color) color.push_back({n.hu, n.rgb.r, n.rgb.g, n.rgb.b});
  j["color"] = color;
  j["opacity"] = opacityJson(vp.opacity);
  if (!vp.gradientOpacity.empty()) j["gradientOpacity"] = opacityJson(vp.gradientOpacity);
  if (!vp.tf2d.empty()) j["tf2d"] = tf2dJson(vp.tf2d);
  j["shading"] = {{"enabled", vp.shade},
                  {"ambient", vp.ambient},
                  {"diffuse", vp.diffuse},
                  {"specular", vp.specular},
                  {"specularPower", vp.specularPower}};
  return j.dump(2) + "\n";
}

VolumeProperty parseSlicerVolumeProperty(const std::string& text, const std::string& origin) {
  Numbers in(text, origin);
  VolumeProperty vp;
  double interpolation = in.next("interpolation type (first number)");
  if (interpolation != 0.0 && interpolation != 1.0 && interpolation != 2.0)
    throw inputError(origin + ": the interpolation type is " + exact(interpolation) +
                     "; it must be 0 (nearest), 1 (linear) or 2 (cubic, read as linear)");
  vp.nearest = interpolation == 0.0;
  double shade = in.next("shading flag (second number)");
  if (shade != 0.0 && shade != 1.0)
    throw inputError(origin + ": the shading flag is " + exact(shade) + "; it must be 0 or 1");
  vp.shade = shade == 1.0;
  vp.diffuse = in.next("diffuse reflection (third number)");
  vp.ambient = in.next("ambient reflection (fourth number)");
  vp.specular = in.next("specular reflection (fifth number)");
  vp.specularPower = in.next("specular power (sixth number)");
  vp.opacity = opacityNodes(in.function("scalar opacity function", 2));
  vp.gradientOpacity = opacityNodes(in.function("gradient opacity function", 2));
  for (const auto& r : in.function("colour function", 4))
    vp.color.push_back({r[0], {r[1], r[2], r[3]}});
  // Slicer writes a constant 1 when the gradient opacity is off: keep the property plain.
  if (!hasGradientOpacity(vp)) vp.gradientOpacity.clear();
  validate(vp, origin);
  return vp;
}

std::string toSlicerVolumeProperty(const VolumeProperty& vp) {
  std::vector<std::vector<double>> opacity, gradient, color;
  if (vp.curve == TfCurve::Smooth) {
    for (const ControlPoint& c : renderTable(vp)) {
      opacity.push_back({c.hu, c.rgba.a});
      color.push_back({c.hu, c.rgba.r, c.rgba.g, c.rgba.b});
    }
  } else {
    for (const auto& n : vp.opacity) opacity.push_back({n.x, n.opacity});
    for (const auto& n : vp.color) color.push_back({n.hu, n.rgb.r, n.rgb.g, n.rgb.b});
  }
  for (const auto& n : vp.gradientOpacity) gradient.push_back({n.x, n.opacity});
  if (gradient.empty()) gradient = {{0.0, 1.0}, {255.0, 1.0}};  // Slicer's "off"
  std::string out = std::string(vp.nearest ? "0" : "1") + "\n" + (vp.shade ? "1" : "0") + "\n";
  for (double v : {vp.diffuse, vp.ambient, vp.specular, vp.specularPower}) out += exact(v) + "\n";
  return out + vpFunction(opacity, 2) + vpFunction(gradient, 2) + vpFunction(color, 4);
}

VolumeProperty readVolumePropertyFile(const std::string& path) {
  namespace fs = std::filesystem;
  const std::string ext = lowerExtension(path);
  if (ext != ".json" && ext != ".vp")
    throw inputError(path + ": a transfer function file ends in .json (Voxray) or .vp (3D Slicer)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw inputError(path + ": cannot open the transfer function file; check the path");
  // A transfer function is a few kB; more than 16 MB is not one (asked before reading it).
  constexpr std::uintmax_t kMaxBytes = std::uintmax_t(16) << 20;
  std::error_code ec;
  if (fs::file_size(path, ec) > kMaxBytes && !ec)
    throw inputError(path + ": over 16 MB, too large for a transfer function file");
  std::ostringstream text;
  text << in.rdbuf();
  if (ext == ".json") return parseVolumePropertyJson(text.str(), path);
  VolumeProperty vp = parseSlicerVolumeProperty(text.str(), path);
  vp.name = fs::path(path).stem().string();
  return vp;
}

void writeVolumePropertyFile(const VolumeProperty& vp, const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".json" && ext != ".vp")
    throw outputError(path + ": name the file .json (Voxray) or .vp (3D Slicer)");
  std::string text = ext == ".json" ? toVolumePropertyJson(vp) : toSlicerVolumeProperty(vp);
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw outputError(path + ": cannot write the transfer function; check the folder");
}

}  // namespace voxray
