#include "study_state.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "value_look.h"

namespace voxray {

namespace {

constexpr WindowLevel kCtDefaultWindow{400.0, 40.0};

// The quality choice's and slice interpolation's lines in RenderStateModel::toText:
// preferences too.
bool isQualityLine(const std::string& key) { return key.rfind("ui-", 0) == 0; }

// The key of a key=value line of RenderStateModel::toText.
std::string keyOf(const std::string& line) { return line.substr(0, line.find('=')); }

// The lines of TEXT (key=value lines) whose key KEEP accepts, in their order.
template <class Keep>
std::string linesWhere(const std::string& text, Keep keep) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line))
    if (keep(keyOf(line))) out += line + "\n";
  return out;
}

// The lines of TEXT (RenderStateModel::toText) that hold preferences.
std::string preferenceLines(const std::string& text) {
  return linesWhere(text,
                    [](const std::string& key) { return isPreference(key) || isQualityLine(key); });
}

// The preferences in HU: a volume whose values are not HU gets its own (value_look.h).
bool isHuValued(const std::string& key) {
  return key == "preset" || key == "tf" || key == "opacity-unit" || key == "gradient-opacity" ||
         key == "preset-shift" || key == "iso" || key == "window";
}

// TEXT's lines, with the HU-valued ones taken from HU's instead (linesWhere isHuValued);
// in TEXT's order, which fromText applies them in (a preset before its table).
std::string withHuLines(const std::string& text, const std::string& hu) {
  std::map<std::string, std::string> huLine;
  std::istringstream h(hu);
  std::string line, out;
  while (std::getline(h, line)) huLine[keyOf(line)] = line;
  std::istringstream in(text);
  while (std::getline(in, line)) {
    const std::string key = keyOf(line);
    if (!isHuValued(key)) {
      out += line + "\n";
    } else if (auto it = huLine.find(key); it != huLine.end()) {
      out += it->second + "\n";
    }
  }
  return out;
}

// Every per-study render parameter of FROM into TO, through the specs so that a parameter
// added later is covered without a second list. The specs run in declaration order:
// "light" (which fixes the light) before "light-follows-camera".
void copyStudyParams(const RenderParams& from, RenderParams& to) {
  for (const auto& spec : renderParamSpecs())
    if (!isPreference(spec.key) && spec.key != "size") spec.parse(to, spec.format(from));
}

// The appearance V opens with: a volume whose values are not HU gets its iso range, dvr
// table and mip window from its own histogram, the user's HU look kept aside; a CT gets
// that look back (its HU lines only: a mode or gradient chosen meanwhile stays).
void applyLookFor(AppModels& m, const Volume& v) {
  if (valuesAreHu(v)) {
    if (m.huLook) applyPreferences(m.render, *std::exchange(m.huLook, std::nullopt));
    return;
  }
  if (!m.huLook) m.huLook = linesWhere(preferencesText(m.render), isHuValued);
  const ValueLook look = valueLook(v);
  m.render.update(kAppearance, [&](RenderParams& p) { applyValueLook(p, look); });
}

}  // namespace

const std::vector<std::string>& preferenceKeys() {
  // The look the user chose and the camera's projection; not where they looked or what
  // they cut away.
  static const std::vector<std::string> keys = {
      // presets and their adjustments
      "mode", "preset", "tf", "opacity-unit", "gradient-opacity", "preset-shift", "iso", "window",
      // reconstruction and compositing
      "gradient", "interp", "step", "refine", "jitter", "shading", "opacity-correction",
      "early-termination",
      // light terms, colours, projection
      "ambient", "diffuse", "specular", "shininess", "surface-color", "background", "projection",
      "fov"};
  return keys;
}

bool isPreference(const std::string& key) {
  const auto& keys = preferenceKeys();
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

std::string preferencesText(const RenderStateModel& m) { return preferenceLines(m.toText()); }

std::string preferencesText(const AppModels& m) {
  const std::string own = preferencesText(m.render);
  return m.huLook ? withHuLines(own, *m.huLook) : own;
}

void applyPreferences(RenderStateModel& m, const std::string& text) {
  m.fromText(preferenceLines(text));
}

InitialWindow initialWindow(const Volume& v) {
  if (v.window) {
    const std::string& why = v.window->explanation;
    return {{v.window->width, v.window->level},
            why.empty() ? v.window->origin : why + " (" + v.window->origin + ")"};
  }
  if (valuesAreHu(v)) return {kCtDefaultWindow, "CT default (no window given)"};
  const ValueRange r = storedRange(v);
  const double a = v.toPhysical(r.min), b = v.toPhysical(r.max);
  const std::string what = v.modality.empty() ? "modality unknown" : v.modality;
  return {{std::max(std::abs(b - a), 1.0), 0.5 * (a + b)},
          "value range (" + what + ", no window given)"};
}

void openStudy(AppModels& m, std::shared_ptr<const Volume> v, std::string name,
               const std::map<std::string, std::string>& values) {
  openStudy(m, VolumeSeries{std::move(v)}, std::move(name), values, 0);
}

void openStudy(AppModels& m, VolumeSeries series, std::string name,
               const std::map<std::string, std::string>& values, int timePoint) {
  timePoint = std::clamp(timePoint, 0, int(series.size()) - 1);
  const std::shared_ptr<const Volume> v = series.at(size_t(timePoint));
  std::map<std::string, std::string> forStudy;
  for (const auto& [key, value] : values)
    if (!isPreference(key)) forStudy.emplace(key, value);
  auto& previous = m.previousStudy;
  previous.valid = !m.document.empty();
  if (previous.valid) {
    previous.render = m.render.params();
    previous.wl = m.windowLevel.value();
    previous.wlSource = m.windowLevel.source();
    previous.dims = m.crosshair.dims();
    previous.crosshair = m.crosshair.voxel();
    previous.source = m.source;
    previous.spacingMm = m.crosshair.spacingMm();
    previous.direction = m.crosshair.direction();
  }
  m.render.update(kCamera | kClip | kLight,
                  [](RenderParams& p) { copyStudyParams(RenderParams{}, p); });
  applyLookFor(m, *v);
  if (!forStudy.empty()) m.render.applyValues(forStudy);
  const InitialWindow w = initialWindow(*v);
  m.windowLevel.reset(w.wl, w.source);
  m.crosshair.setGeometry(v->dims, v->spacingMm, v->direction);
  m.measurements.clear();  // a study's own; a session brings them back
  m.annotations.clear();
  m.segmentation.clear();  // as are its segments
  // Last: whoever hears the document change sees the new study's state with it.
  m.document.setSeries(std::move(series), std::move(name), timePoint);
}

void restorePreviousStudy(AppModels& m) {
  auto& previous = m.previousStudy;
  if (previous.valid) {
    previous.valid = false;
    m.render.update(kCamera | kClip | kLight,
                    [&](RenderParams& p) { copyStudyParams(previous.render, p); });
    m.windowLevel.reset(previous.wl, previous.wlSource);
    m.crosshair.setGeometry(previous.dims, previous.spacingMm, previous.direction);
    m.crosshair.setVoxel(previous.crosshair);
    m.source = previous.source;
  }
  m.document.restorePrevious();
  if (m.document.volume()) applyLookFor(m, *m.document.volume());
}

}  // namespace voxray
