#include "voxray/engine/render_params.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "text_parse.h"
#include "voxray/io/error.h"

namespace voxray {
using namespace text;

const char* toString(Mode m) {
  switch (m) {
    case Mode::Iso:
      return "iso";
    case Mode::Dvr:
      return "dvr";
    case Mode::Mip:
      return "mip";
  }
  return "?";
}
const char* toString(Gradient g) {
  switch (g) {
    case Gradient::Central:
      return "central";
    case Gradient::Sobel:
      return "sobel";
    case Gradient::ZuckerHummel:
      return "zucker-hummel";
  }
  return "?";
}
const char* toString(Interp i) { return i == Interp::Nearest ? "nearest" : "linear"; }

Mode parseMode(const std::string& s) {
  if (s == "iso") return Mode::Iso;
  if (s == "dvr") return Mode::Dvr;
  if (s == "mip") return Mode::Mip;
  throw inputError("--mode: '" + s + "' is not one of iso, dvr, mip");
}
Gradient parseGradient(const std::string& s) {
  if (s == "central") return Gradient::Central;
  if (s == "sobel") return Gradient::Sobel;
  if (s == "zucker-hummel" || s == "zh") return Gradient::ZuckerHummel;
  throw inputError("--gradient: '" + s + "' is not one of central, sobel, zucker-hummel");
}
Interp parseInterp(const std::string& s) {
  if (s == "nearest") return Interp::Nearest;
  if (s == "linear" || s == "trilinear") return Interp::Linear;
  throw inputError("--interp: '" + s + "' is not one of nearest, linear");
}

namespace {

void parseSize(RenderParams& p, const std::string& s) {
  auto x = s.find('x');
  if (x == std::string::npos)
    throw inputError("--size: expected WxH, e.g. 1024x768, got '" + s + "'");
  int w = toInt("size", s.substr(0, x)), h = toInt("size", s.substr(x + 1));
  if (w < 1 || h < 1 || w > 16384 || h > 16384)
    throw inputError("--size: " + s + " is outside 1x1 ... 16384x16384");
  p.width = w;
  p.height = h;
}

void parseClip(RenderParams& p, const std::string& s) {
  auto v = toDoubles("clip", s, 6, 6);
  for (int a = 0; a < 3; ++a) {
    double lo = v[2 * a], hi = v[2 * a + 1];
    if (lo < 0.0 || hi > 1.0 || lo > hi)
      throw inputError(
          "--clip: each pair must satisfy 0 <= lo <= hi <= 1 (fractions of the "
          "volume), got '" +
          s + "'");
    p.clip.lo[a] = lo;
    p.clip.hi[a] = hi;
  }
}

// "HU:R:G:B:A,HU:R:G:B:A,...": sorted by HU, stable, so coincident points keep their order
// (the step goes from the first to the last of them).
std::vector<ControlPoint> parseTransferFunction(const std::string& s) {
  std::vector<ControlPoint> points;
  std::istringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::vector<double> v;
    std::istringstream fields(item);
    std::string field;
    while (std::getline(fields, field, ':')) v.push_back(toDouble("tf", field));
    if (v.size() != 5 || !std::isfinite(v[0]))
      throw inputError("--tf: each point is HU:R:G:B:A with a finite HU, got '" + item + "'");
    for (int c = 1; c < 5; ++c)
      if (!(v[c] >= 0.0 && v[c] <= 1.0))
        throw inputError("--tf: colour and opacity must lie in 0 ... 1, got '" + item + "'");
    points.push_back({v[0], {v[1], v[2], v[3], v[4]}});
  }
  std::stable_sort(points.begin(), points.end(),
                   [](const ControlPoint& a, const ControlPoint& b) { return a.hu < b.hu; });
  return points;
}

std::string formatTransferFunction(const std::vector<ControlPoint>& points) {
  std::string out;
  for (const ControlPoint& c : points) {
    if (!out.empty()) out += ",";
    out += fmt(c.hu);
    for (int k = 0; k < 4; ++k) out += ":" + fmt(c.rgba[k]);
  }
  return out;
}

double positive(const std::string& key, const std::string& s) {
  double v = toDouble(key, s);
  if (v <= 0.0) throw inputError("--" + key + ": must be greater than 0, got '" + s + "'");
  return v;
}

double unit(const std::string& key, const std::string& s) {
  double v = toDouble(key, s);
  if (v < 0.0 || v > 1.0) throw inputError("--" + key + ": must lie in 0 ... 1, got '" + s + "'");
  return v;
}

std::vector<ParamSpec> makeSpecs() {
  using P = RenderParams;
  using S = const std::string&;
  return {
      {"size", "WxH", "image size in pixels", [](P& p, S s) { parseSize(p, s); },
       [](const P& p) { return std::to_string(p.width) + "x" + std::to_string(p.height); }},
      {"mode", "iso|dvr|mip", "first-hit surface, direct volume rendering, or maximum intensity",
       [](P& p, S s) { p.mode = parseMode(s); },
       [](const P& p) { return std::string(toString(p.mode)); }},
      {"preset", "NAME", "transfer-function preset from resources/presets (voxray-cli presets)",
       [](P& p, S s) {
         // Saved state is one key=value per line: a name with a line break would not read
         // back (found by the render-parameter fuzzer).
         if (std::any_of(s.begin(), s.end(), [](unsigned char c) { return c < 0x20 || c == 0x7F; }))
           throw inputError(
               "--preset: a preset name is one line of printable text; see "
               "voxray-cli presets");
         p.preset = s;
       },
       [](const P& p) { return p.preset; }},
      {"tf", "HU:R:G:B:A,...",
       "custom transfer function instead of the preset's: colour and opacity (0 ... 1, opacity "
       "per voxel) at each HU, linear between; a repeated HU makes a step",
       [](P& p, S s) { p.transferFunction = parseTransferFunction(s); },
       [](const P& p) { return formatTransferFunction(p.transferFunction); }},
      {"preset-shift", "HU", "move the preset's transfer function along HU",
       [](P& p, S s) { p.presetShiftHu = toDouble("preset-shift", s); },
       [](const P& p) { return fmt(p.presetShiftHu); }},
      {"iso", "LO[,HI]", "HU range of the first-hit surface",
       [](P& p, S s) {
         auto v = toDoubles("iso", s, 1, 2);
         p.isoLo = v[0];
         p.isoHi = v.size() > 1 ? v[1] : 32767.0;
         if (p.isoHi < p.isoLo) throw inputError("--iso: HI must not be below LO, got '" + s + "'");
       },
       [](const P& p) { return fmt(p.isoLo) + "," + fmt(p.isoHi); }},
      {"gradient", "central|sobel|zucker-hummel", "gradient operator for normals",
       [](P& p, S s) { p.gradient = parseGradient(s); },
       [](const P& p) { return std::string(toString(p.gradient)); }},
      {"interp", "nearest|linear", "sample reconstruction",
       [](P& p, S s) { p.interp = parseInterp(s); },
       [](const P& p) { return std::string(toString(p.interp)); }},
      {"step", "MM", "sampling distance along the ray in mm (0 = half the smallest spacing)",
       [](P& p, S s) {
         p.stepMm = toDouble("step", s);
         if (p.stepMm < 0.0) throw inputError("--step: must not be negative, got '" + s + "'");
       },
       [](const P& p) { return fmt(p.stepMm); }},
      {"refine", "N", "bisection steps refining an iso hit (0 ... 16)",
       [](P& p, S s) {
         p.refine = toInt("refine", s);
         if (p.refine < 0 || p.refine > 16) throw inputError("--refine: must lie in 0 ... 16");
       },
       [](const P& p) { return std::to_string(p.refine); }},
      {"shading", "on|off", "Blinn-Phong lighting from the gradient",
       [](P& p, S s) { p.shading = toBool("shading", s); },
       [](const P& p) { return std::string(p.shading ? "on" : "off"); }},
      {"opacity-correction", "on|off", "scale dvr opacity to the step size",
       [](P& p, S s) { p.opacityCorrection = toBool("opacity-correction", s); },
       [](const P& p) { return std::string(p.opacityCorrection ? "on" : "off"); }},
      {"jitter", "on|off", "per-pixel offset of the first sample (removes wood-grain banding)",
       [](P& p, S s) { p.jitter = toBool("jitter", s); },
       [](const P& p) { return std::string(p.jitter ? "on" : "off"); }},
      {"early-termination", "A", "dvr stops a ray at this opacity (1 = never)",
       [](P& p, S s) { p.earlyTermination = unit("early-termination", s); },
       [](const P& p) { return fmt(p.earlyTermination); }},
      {"window", "W,L", "mip grey window width and level in HU",
       [](P& p, S s) {
         auto v = toDoubles("window", s, 2, 2);
         if (v[0] < 0.0)
           throw inputError("--window: width must not be negative (0 = the volume's range)");
         p.windowWidth = v[0];
         p.windowLevel = v[1];
       },
       [](const P& p) { return fmt(p.windowWidth) + "," + fmt(p.windowLevel); }},
      {"azimuth", "DEG", "orbit around the patient's long axis (0 = anterior, 90 = left)",
       [](P& p, S s) { p.camera.azimuthDeg = toDouble("azimuth", s); },
       [](const P& p) { return fmt(p.camera.azimuthDeg); }},
      {"elevation", "DEG", "orbit up towards superior (90 = from above)",
       [](P& p, S s) { p.camera.elevationDeg = toDouble("elevation", s); },
       [](const P& p) { return fmt(p.camera.elevationDeg); }},
      {"zoom", "F", "magnification (1 = whole volume in view)",
       [](P& p, S s) { p.camera.zoom = positive("zoom", s); },
       [](const P& p) { return fmt(p.camera.zoom); }},
      {"distance", "MM", "eye to volume centre (0 = automatic)",
       [](P& p, S s) {
         p.camera.distanceMm = toDouble("distance", s);
         if (p.camera.distanceMm < 0.0) throw inputError("--distance: must not be negative");
       },
       [](const P& p) { return fmt(p.camera.distanceMm); }},
      {"pan", "X,Y", "move the view in mm (right, up)",
       [](P& p, S s) {
         auto v = toDoubles("pan", s, 2, 2);
         p.camera.panMm = {v[0], v[1]};
       },
       [](const P& p) { return fmt(p.camera.panMm.x) + "," + fmt(p.camera.panMm.y); }},
      {"projection", "perspective|orthographic", "camera projection",
       [](P& p, S s) {
         if (s == "perspective")
           p.camera.projection = Projection::Perspective;
         else if (s == "orthographic" || s == "ortho")
           p.camera.projection = Projection::Orthographic;
         else
           throw inputError("--projection: '" + s + "' is not perspective or orthographic");
       },
       [](const P& p) {
         return std::string(p.camera.projection == Projection::Perspective ? "perspective"
                                                                           : "orthographic");
       }},
      {"fov", "DEG", "perspective field of view (vertical)",
       [](P& p, S s) {
         p.camera.fovDeg = toDouble("fov", s);
         if (p.camera.fovDeg <= 0.0 || p.camera.fovDeg >= 170.0)
           throw inputError("--fov: must lie between 0 and 170 degrees");
       },
       [](const P& p) { return fmt(p.camera.fovDeg); }},
      {"clip", "X0,X1,Y0,Y1,Z0,Z1", "clip box in fractions of the volume (0 ... 1)",
       [](P& p, S s) { parseClip(p, s); },
       [](const P& p) {
         std::string out;
         for (int a = 0; a < 3; ++a)
           out += (a ? "," : "") + fmt(p.clip.lo[a]) + "," + fmt(p.clip.hi[a]);
         return out;
       }},
      {"light", "X,Y,Z", "point light in mm, patient LPS from the volume centre (fixes the light)",
       [](P& p, S s) {
         p.light.position = toVec3("light", s);
         p.light.followCamera = false;
       },
       [](const P& p) { return fmt(p.light.position); }},
      {"light-follows-camera", "on|off", "light position is relative to the eye",
       [](P& p, S s) { p.light.followCamera = toBool("light-follows-camera", s); },
       [](const P& p) { return std::string(p.light.followCamera ? "on" : "off"); }},
      {"ambient", "K", "ambient light 0 ... 1",
       [](P& p, S s) { p.light.ambient = unit("ambient", s); },
       [](const P& p) { return fmt(p.light.ambient); }},
      {"diffuse", "K", "diffuse light 0 ... 1",
       [](P& p, S s) { p.light.diffuse = unit("diffuse", s); },
       [](const P& p) { return fmt(p.light.diffuse); }},
      {"specular", "K", "specular light 0 ... 1",
       [](P& p, S s) { p.light.specular = unit("specular", s); },
       [](const P& p) { return fmt(p.light.specular); }},
      {"shininess", "N", "specular exponent",
       [](P& p, S s) { p.light.shininess = positive("shininess", s); },
       [](const P& p) { return fmt(p.light.shininess); }},
      {"surface-color", "R,G,B", "iso surface colour 0 ... 1",
       [](P& p, S s) { p.surfaceColor = glm::clamp(toVec3("surface-color", s), 0.0, 1.0); },
       [](const P& p) { return fmt(p.surfaceColor); }},
      {"background", "R,G,B", "background colour 0 ... 1",
       [](P& p, S s) { p.background = glm::clamp(toVec3("background", s), 0.0, 1.0); },
       [](const P& p) { return fmt(p.background); }},
  };
}

}  // namespace

const std::vector<ParamSpec>& renderParamSpecs() {
  static const std::vector<ParamSpec> specs = makeSpecs();
  return specs;
}

std::string toText(const RenderParams& p) {
  std::string out;
  for (const auto& s : renderParamSpecs()) out += s.key + "=" + s.format(p) + "\n";
  return out;
}

void fromText(RenderParams& p, const std::string& text) {
  std::istringstream in(text);
  std::string line;
  const auto& specs = renderParamSpecs();
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    auto eq = line.find('=');
    if (eq == std::string::npos)
      throw inputError("render parameters: line '" + line + "' has no '='");
    std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    auto it =
        std::find_if(specs.begin(), specs.end(), [&](const ParamSpec& s) { return s.key == key; });
    if (it == specs.end()) throw inputError("render parameters: unknown key '" + key + "'");
    it->parse(p, value);
  }
}

double effectiveStepMm(const RenderParams& p, double minSpacingMm) {
  return p.stepMm > 0.0 ? p.stepMm : 0.5 * minSpacingMm;
}

}  // namespace voxray
