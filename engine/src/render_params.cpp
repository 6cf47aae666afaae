#include "voxray/engine/render_params.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

#include "segment_tf.h"
#include "text_parse.h"
#include "voxray/io/error.h"

namespace voxray {
using namespace text;

namespace {

// The enumerations' one table each: names (what parses and formats), titles (what a control
// shows) and other accepted spellings, in the enum's order.
const std::vector<EnumLabel>& modeLabels() {
  static const std::vector<EnumLabel> l = {
      {"iso", "Iso surface", {}}, {"dvr", "Volume (DVR)", {}}, {"mip", "MIP", {}}};
  return l;
}
const std::vector<EnumLabel>& gradientLabels() {
  static const std::vector<EnumLabel> l = {{"central", "Central difference", {}},
                                           {"sobel", "Sobel", {}},
                                           {"zucker-hummel", "Zucker-Hummel", {"zh"}}};
  return l;
}
const std::vector<EnumLabel>& interpLabels() {
  static const std::vector<EnumLabel> l = {{"nearest", "Nearest", {}},
                                           {"linear", "Trilinear", {"trilinear"}}};
  return l;
}
const std::vector<EnumLabel>& projectionLabels() {
  static const std::vector<EnumLabel> l = {{"perspective", "Perspective", {}},
                                           {"orthographic", "Orthographic", {"ortho"}}};
  return l;
}
const std::vector<EnumLabel>& lightingLabels() {
  static const std::vector<EnumLabel> l = {{"phong", "Phong", {}},
                                           {"shadows", "Shadows", {}},
                                           {"ao", "Ambient occlusion", {}},
                                           {"cinematic", "Cinematic (path tracer)", {}}};
  return l;
}

const char* name(const std::vector<EnumLabel>& labels, int value) {
  return value >= 0 && size_t(value) < labels.size() ? labels[size_t(value)].name.c_str() : "?";
}

}  // namespace

const char* toString(Mode m) { return name(modeLabels(), int(m)); }
const char* toString(Gradient g) { return name(gradientLabels(), int(g)); }
const char* toString(Interp i) { return name(interpLabels(), int(i)); }
const char* toString(Lighting l) { return name(lightingLabels(), int(l)); }
Mode parseMode(const std::string& s) { return Mode(labelIndex("mode", modeLabels(), s)); }
Gradient parseGradient(const std::string& s) {
  return Gradient(labelIndex("gradient", gradientLabels(), s));
}
Interp parseInterp(const std::string& s) { return Interp(labelIndex("interp", interpLabels(), s)); }
Lighting parseLighting(const std::string& s) {
  return Lighting(labelIndex("lighting", lightingLabels(), s));
}

namespace {

using P = RenderParams;
using S = const std::string&;

const ParamDomain kSizeDomain = ParamDomain().atLeast(1).atMost(16384);
const ParamDomain kFractionDomain = ParamDomain().atLeast(0).atMost(1).steps(0.01, 3);

void parseSize(RenderParams& p, const std::string& s) {
  auto x = s.find('x');
  if (x == std::string::npos)
    throw inputError("--size: expected WxH, e.g. 1024x768, got '" + s + "'");
  int w = toInt("size", s.substr(0, x)), h = toInt("size", s.substr(x + 1));
  if (!kSizeDomain.contains(w) || !kSizeDomain.contains(h))
    throw inputError("--size: " + s + " is outside 1x1 ... 16384x16384");
  p.width = w;
  p.height = h;
}

// --adaptive-image on: this threshold (levels of 255) at 4-pixel spacing; measured in
// tests/engine/adaptive_image_test.cpp and docs/bench (issue 40).
constexpr double kAdaptiveImageOnLevels = 8.0;

void parseAdaptiveImage(RenderParams& p, const std::string& s) {
  if (s == "off" || s == "on") {
    p.adaptiveImage = s == "on" ? kAdaptiveImageOnLevels : -1.0;
    p.adaptiveImageSpacing = 4;
    return;
  }
  auto v = toDoubles("adaptive-image", s, 1, 2);
  if (!(v[0] >= 0.0 && v[0] <= 255.0))
    throw inputError("--adaptive-image: THRESHOLD is 0 ... 255 levels (or off), got '" + s + "'");
  const double k = v.size() > 1 ? v[1] : 4.0;
  if (!(k >= 2.0 && k <= 8.0) || k != std::floor(k))
    throw inputError("--adaptive-image: K is a whole 2 ... 8 pixels, got '" + s + "'");
  p.adaptiveImage = v[0];
  p.adaptiveImageSpacing = int(k);
}

void parseClip(RenderParams& p, const std::string& s) {
  auto v = toDoubles("clip", s, 6, 6);
  for (double f : v) checkInDomain("clip", kFractionDomain, f, s);
  for (int a = 0; a < 3; ++a) {
    double lo = v[2 * a], hi = v[2 * a + 1];
    if (lo > hi)
      throw inputError(
          "--clip: each pair must satisfy 0 <= lo <= hi <= 1 (fractions of the "
          "volume), got '" +
          s + "'");
    p.clip.lo[a] = lo;
    p.clip.hi[a] = hi;
  }
}

// "X:Y:...,X:Y:...": each comma-separated item with its colon-separated numbers (KEY names
// the flag when one is not a number), the shape of both point lists below.
std::vector<std::pair<std::string, std::vector<double>>> colonPoints(const std::string& key,
                                                                     const std::string& s) {
  std::vector<std::pair<std::string, std::vector<double>>> out;
  std::istringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::vector<double> v;
    std::istringstream fields(item);
    std::string field;
    while (std::getline(fields, field, ':')) v.push_back(toDouble(key, field));
    out.emplace_back(item, std::move(v));
  }
  return out;
}

// "HU:R:G:B:A,HU:R:G:B:A,...": sorted by HU, stable, so coincident points keep their order
// (the step goes from the first to the last of them).
std::vector<ControlPoint> parseTransferFunction(const std::string& s) {
  std::vector<ControlPoint> points;
  for (const auto& [item, v] : colonPoints("tf", s)) {
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

// "G:A,G:A,...": |gradient| in HU/mm and a factor 0 ... 1, sorted by |gradient| (stable).
std::vector<glm::dvec2> parseGradientOpacity(const std::string& s) {
  std::vector<glm::dvec2> points;
  for (const auto& [item, v] : colonPoints("gradient-opacity", s)) {
    if (v.size() != 2 || !std::isfinite(v[0]) || v[0] < 0.0)
      throw inputError(
          "--gradient-opacity: each point is G:A, G a gradient magnitude in HU/mm (0 or more), "
          "got '" +
          item + "'");
    if (!(v[1] >= 0.0 && v[1] <= 1.0))
      throw inputError("--gradient-opacity: the factor A must lie in 0 ... 1, got '" + item + "'");
    points.push_back({v[0], v[1]});
  }
  std::stable_sort(points.begin(), points.end(),
                   [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x; });
  return points;
}

std::string formatGradientOpacity(const std::vector<glm::dvec2>& points) {
  std::string out;
  for (const glm::dvec2& g : points) out += (out.empty() ? "" : ",") + fmt(g.x) + ":" + fmt(g.y);
  return out;
}

}  // namespace

std::vector<ControlPoint> parseTfPoints(const std::string& s) { return parseTransferFunction(s); }
std::string formatTfPoints(const std::vector<ControlPoint>& points) {
  return formatTransferFunction(points);
}

SegmentMask parseSegmentMask(const std::string& text) {
  SegmentMask m;
  if (text.empty() || text == "off") return m;
  const auto colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  const auto bad = [&](const std::string& why) {
    return inputError("--segment-mask: " + why + ", got '" + text +
                      "' (off, show:L1,L2,... or hide:L1,...; L a segment's label 1 ... 255)");
  };
  if (kind == "show")
    m.kind = SegmentMask::Kind::Show;
  else if (kind == "hide")
    m.kind = SegmentMask::Kind::Hide;
  else
    throw bad("it starts with off, show or hide");
  if (colon == std::string::npos || colon + 1 == text.size())
    throw bad("show and hide need the labels after ':'");
  std::istringstream in(text.substr(colon + 1));
  std::string item;
  while (std::getline(in, item, ',')) {
    size_t used = 0;
    int label = -1;
    try {
      label = std::stoi(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || item.empty() || label < 1 || label > 255)
      throw bad("'" + item + "' is not a label 1 ... 255");
    m.labels.push_back(label);
  }
  if (m.labels.empty() || text.back() == ',') throw bad("a label list has no empty items");
  std::sort(m.labels.begin(), m.labels.end());
  m.labels.erase(std::unique(m.labels.begin(), m.labels.end()), m.labels.end());
  return m;
}

std::string toString(const SegmentMask& m) {
  if (m.kind == SegmentMask::Kind::Off) return "off";
  std::string out = m.kind == SegmentMask::Kind::Show ? "show:" : "hide:";
  for (size_t i = 0; i < m.labels.size(); ++i) {
    if (i > 0) out += ',';
    out += std::to_string(m.labels[i]);
  }
  return out;
}

namespace {

// Builders for the common kinds. FIELD is a generic lambda giving the field of a
// RenderParams, const or not, so that one accessor serves both parse and format.
template <class Field>
ParamSpec number(std::string key, std::string hint, std::string help, ParamDomain d, Field field) {
  ParamSpec s{key, std::move(hint), std::move(help), d, {}, {}};
  s.parse = [key, d, field](P& p, S text) {
    field(p) = checkInDomain(key, d, toDouble(key, text), text);
  };
  s.format = [field](const P& p) { return fmt(field(p)); };
  return s;
}

template <class Field>
ParamSpec whole(std::string key, std::string hint, std::string help, ParamDomain d, Field field) {
  ParamSpec s{key, std::move(hint), std::move(help), d, {}, {}};
  s.parse = [key, d, field](P& p, S text) {
    field(p) = int(checkInDomain(key, d, toInt(key, text), text));
  };
  s.format = [field](const P& p) { return std::to_string(field(p)); };
  return s;
}

template <class Field>
ParamSpec choice(std::string key, std::string help, const std::vector<EnumLabel>& labels,
                 Field field) {
  ParamSpec s{key, labelNames(labels, "|"), std::move(help), ParamDomain().choices(labels), {}, {}};
  s.parse = [key, labels, field](P& p, S text) {
    using Enum = std::remove_reference_t<decltype(field(p))>;
    field(p) = Enum(labelIndex(key, labels, text));
  };
  s.format = [labels, field](const P& p) { return labels[size_t(field(p))].name; };
  return s;
}

template <class Field>
ParamSpec toggle(std::string key, std::string help, Field field) {
  ParamSpec s{key, "on|off", std::move(help), {}, {}, {}};
  s.parse = [key, field](P& p, S text) { field(p) = toBool(key, text); };
  s.format = [field](const P& p) { return std::string(field(p) ? "on" : "off"); };
  return s;
}

// The field of a RenderParams a spec reads and writes. PATH is a member path (light.ambient),
// which parentheses would break: p.(path) is not C++.
#define FIELD(path) \
  [](auto& p) -> auto& { return p.path; }  // NOLINT(bugprone-macro-parentheses)

std::vector<ParamSpec> makeSpecs() {
  const ParamDomain unit = ParamDomain().atLeast(0).atMost(1).steps(0.05, 2);
  const ParamDomain positive = ParamDomain().above(0);
  const ParamDomain notNegative = ParamDomain().atLeast(0);
  const ParamDomain none;
  return {
      {"size", "WxH", "image size in pixels", kSizeDomain, [](P& p, S s) { parseSize(p, s); },
       [](const P& p) { return std::to_string(p.width) + "x" + std::to_string(p.height); }},
      choice("mode", "first-hit surface, direct volume rendering, or maximum intensity",
             modeLabels(), FIELD(mode)),
      {"preset", "NAME", "transfer-function preset from resources/presets (voxray-cli presets)",
       none,
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
       none, [](P& p, S s) { p.transferFunction = parseTransferFunction(s); },
       [](const P& p) { return formatTransferFunction(p.transferFunction); }},
      number("opacity-unit", "MM",
             "ray length in mm over which the table's opacities hold (0 = the smallest voxel "
             "spacing, as the presets)",
             ParamDomain().atLeast(0).in("mm"), FIELD(opacityUnitMm)),
      {"gradient-opacity", "G:A,...",
       "dvr: opacity times a factor A (0 ... 1) of the gradient magnitude G (HU/mm), linear "
       "between points, so homogeneous regions can fade and boundaries show (empty = off)",
       none, [](P& p, S s) { p.gradientOpacity = parseGradientOpacity(s); },
       [](const P& p) { return formatGradientOpacity(p.gradientOpacity); }},
      {"tf2d", "rect:HU0,HU1,G0,G1,R,G,B,A[,SOFT];tri:...",
       "dvr: a 2D transfer function over HU and gradient magnitude G (HU/mm) that replaces the "
       "table's colour and opacity and the gradient opacity: rectangles, and triangles widening "
       "from |gradient| 0 to [HU0, HU1] at G1, cut to [G0, G1], colour R,G,B, peak opacity A, "
       "soft edge SOFT (0 ... 1); 'gmax:G' tops the table's gradient axis (empty = off)",
       none, [](P& p, S s) { p.tf2d = parseTf2d(s); },
       [](const P& p) { return formatTf2d(p.tf2d); }},
      number("preset-shift", "HU", "move the preset's transfer function along HU",
             ParamDomain().in("HU"), FIELD(presetShiftHu)),
      // Any HU is accepted; a control offers the range of CT values.
      {"iso", "LO[,HI]", "HU range of the first-hit surface",
       ParamDomain().steps(10, 0).in("HU").offer(-3000, 32767),
       [](P& p, S s) {
         auto v = toDoubles("iso", s, 1, 2);
         p.isoLo = v[0];
         p.isoHi = v.size() > 1 ? v[1] : 32767.0;
         if (p.isoHi < p.isoLo) throw inputError("--iso: HI must not be below LO, got '" + s + "'");
       },
       [](const P& p) { return fmt(p.isoLo) + "," + fmt(p.isoHi); }},
      choice("gradient", "gradient operator for normals", gradientLabels(), FIELD(gradient)),
      choice("interp", "sample reconstruction", interpLabels(), FIELD(interp)),
      number("step", "MM", "sampling distance along the ray in mm (0 = half the smallest spacing)",
             ParamDomain().atLeast(0).in("mm"), FIELD(stepMm)),
      whole("refine", "N", "bisection steps refining an iso hit (0 ... 16)",
            ParamDomain().atLeast(0).atMost(16).steps(1, 0), FIELD(refine)),
      toggle("shading", "Blinn-Phong lighting from the gradient", FIELD(shading)),
      toggle("opacity-correction", "scale dvr opacity to the step size", FIELD(opacityCorrection)),
      toggle("jitter", "per-pixel offset of the first sample (removes wood-grain banding)",
             FIELD(jitter)),
      number("adaptive", "E",
             "dvr: longer steps where the table varies little, each changing the composite by at "
             "most E (0 = fixed steps)",
             ParamDomain().atLeast(0).atMost(1).steps(0.005, 3), FIELD(adaptiveError)),
      toggle("preintegrate",
             "dvr: classify each step over the values between its two samples (pre-integrated "
             "table; longer steps keep thin features)",
             FIELD(preintegrate)),
      {"adaptive-image", "off|on|THRESHOLD[,K]",
       "image-space adaptive sampling: rays at every K-th pixel (2 ... 8, default 4) first, "
       "then every pixel of the K x K blocks whose corners differ by THRESHOLD levels (of 255) "
       "or more, the rest bilinear (0 = every block: the plain frame; on = 8,4; off = every "
       "pixel)",
       none, [](P& p, S s) { parseAdaptiveImage(p, s); },
       [](const P& p) {
         if (p.adaptiveImage < 0.0) return std::string("off");
         std::string out = fmt(p.adaptiveImage);
         out += ',';
         out += std::to_string(p.adaptiveImageSpacing);
         return out;
       }},
      {"segment-mask", "off|show:L,...|hide:L,...",
       "dvr with a segmentation: show only what the segments of labels L cover, or hide them "
       "(off = the whole volume)",
       none, [](P& p, S s) { p.segmentMask = parseSegmentMask(s); },
       [](const P& p) { return toString(p.segmentMask); }},
      number("segment-blend", "F",
             "dvr with a segmentation: how strongly a visible segment's colour replaces the "
             "transfer function's (0 ... 1)",
             unit, FIELD(segmentBlend)),
      {"segment-tf", "L:SPEC;...",
       "dvr with a segmentation: segment L's own transfer function, used for the samples it "
       "covers instead of the volume's (and instead of its colour): SPEC a preset name, a .json "
       "or .vp file, or points HU:R:G:B:A,... as --tf; several separated by ';' (off = none)",
       none, [](P& p, S s) { p.segmentTfs = parseSegmentTfs(s); },
       [](const P& p) { return formatSegmentTfs(p.segmentTfs); }},
      number("early-termination", "A", "dvr stops a ray at this opacity (1 = never)", unit,
             FIELD(earlyTermination)),
      {"window", "W,L", "mip grey window width and level in HU", ParamDomain().in("HU"),
       [](P& p, S s) {
         auto v = toDoubles("window", s, 2, 2);
         if (v[0] < 0.0)
           throw inputError("--window: width must not be negative (0 = the volume's range)");
         p.windowWidth = v[0];
         p.windowLevel = v[1];
       },
       [](const P& p) { return fmt(p.windowWidth) + "," + fmt(p.windowLevel); }},
      number("azimuth", "DEG", "orbit around the patient's long axis (0 = anterior, 90 = left)",
             none, FIELD(camera.azimuthDeg)),
      number("elevation", "DEG", "orbit up towards superior (90 = from above)", none,
             FIELD(camera.elevationDeg)),
      number("zoom", "F", "magnification (1 = whole volume in view)", positive, FIELD(camera.zoom)),
      number("distance", "MM", "eye to volume centre (0 = automatic)", notNegative,
             FIELD(camera.distanceMm)),
      {"pan", "X,Y", "move the view in mm (right, up)", none,
       [](P& p, S s) {
         auto v = toDoubles("pan", s, 2, 2);
         p.camera.panMm = {v[0], v[1]};
       },
       [](const P& p) { return fmt(p.camera.panMm.x) + "," + fmt(p.camera.panMm.y); }},
      choice("projection", "camera projection", projectionLabels(), FIELD(camera.projection)),
      number("fov", "DEG", "perspective field of view (vertical)",
             ParamDomain().above(0).below(170), FIELD(camera.fovDeg)),
      {"clip", "X0,X1,Y0,Y1,Z0,Z1", "clip box in fractions of the volume (0 ... 1)",
       kFractionDomain, [](P& p, S s) { parseClip(p, s); },
       [](const P& p) {
         std::string out;
         for (int a = 0; a < 3; ++a)
           out += (a ? "," : "") + fmt(p.clip.lo[a]) + "," + fmt(p.clip.hi[a]);
         return out;
       }},
      // Any position is accepted; a control offers a few metres either way.
      {"light", "X,Y,Z", "point light in mm, patient LPS from the volume centre (fixes the light)",
       ParamDomain().steps(0.1, 2).offer(-5000, 5000),
       [](P& p, S s) {
         p.light.position = toVec3("light", s);
         p.light.followCamera = false;
       },
       [](const P& p) { return fmt(p.light.position); }},
      toggle("light-follows-camera", "light position is relative to the eye",
             FIELD(light.followCamera)),
      number("ambient", "K", "ambient light 0 ... 1", unit, FIELD(light.ambient)),
      number("diffuse", "K", "diffuse light 0 ... 1", unit, FIELD(light.diffuse)),
      number("specular", "K", "specular light 0 ... 1", unit, FIELD(light.specular)),
      // Any positive exponent is accepted; a control stops at 1024, far past the narrowest
      // highlight a CT surface shows.
      number("shininess", "N", "specular exponent", ParamDomain().above(0).offer({}, 1024),
             FIELD(light.shininess)),
      choice("lighting", "lighting model", lightingLabels(), FIELD(lighting)),
      {"surface-color", "R,G,B", "iso surface colour 0 ... 1", none,
       [](P& p, S s) { p.surfaceColor = glm::clamp(toVec3("surface-color", s), 0.0, 1.0); },
       [](const P& p) { return fmt(p.surfaceColor); }},
      {"background", "R,G,B", "background colour 0 ... 1", none,
       [](P& p, S s) { p.background = glm::clamp(toVec3("background", s), 0.0, 1.0); },
       [](const P& p) { return fmt(p.background); }},
  };
}
#undef FIELD

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

const ParamSpec& findRenderParamSpec(const std::string& key) {
  const auto& specs = renderParamSpecs();
  auto it =
      std::find_if(specs.begin(), specs.end(), [&](const ParamSpec& s) { return s.key == key; });
  if (it == specs.end()) throw inputError("render parameters: unknown key '" + key + "'");
  return *it;
}

void fromText(RenderParams& p, const std::string& text) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    auto eq = line.find('=');
    if (eq == std::string::npos)
      throw inputError("render parameters: line '" + line + "' has no '='");
    findRenderParamSpec(line.substr(0, eq)).parse(p, line.substr(eq + 1));
  }
}

void applyRenderValues(RenderParams& p, const std::map<std::string, std::string>& values) {
  for (const auto& kv : values) findRenderParamSpec(kv.first);  // refuses unknown keys
  if (auto it = values.find("preset"); it != values.end()) applyPreset(p, findPreset(it->second));
  for (const auto& spec : renderParamSpecs())
    if (auto it = values.find(spec.key); it != values.end()) spec.parse(p, it->second);
}

}  // namespace voxray
