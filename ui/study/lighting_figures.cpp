#include "lighting_figures.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <string_view>

#include <nlohmann/json.hpp>

#include "voxray/io/error.h"
#include "voxray/io/statistics.h"

namespace voxray {
const std::map<std::string, std::string_view>& embeddedLightingFigures();
}

namespace voxray {

namespace {

const Lighting kModels[] = {Lighting::Phong, Lighting::Shadows, Lighting::Ao, Lighting::Cinematic};

std::string modelName(Lighting l) {
  switch (l) {
    case Lighting::Phong:
      return "Phong";
    case Lighting::Shadows:
      return "Shadows";
    case Lighting::Ao:
      return "AO";
    case Lighting::Cinematic:
      return "Cinematic";
  }
  return "?";
}

std::string fmt(const char* f, double a) {
  char b[64];
  std::snprintf(b, sizeof b, f, a);
  return b;
}

std::string ms(double v) { return fmt(v < 10.0 ? "%.1f ms" : "%.0f ms", v); }

std::string size(int w, int h) { return std::to_string(w) + "\u00d7" + std::to_string(h); }

std::string costText(Lighting l, double frameMs, double precomputeMs) {
  std::string s = ms(frameMs) + (l == Lighting::Cinematic ? " per pass" : "");
  if (l == Lighting::Shadows || l == Lighting::Ao) s += " + " + ms(precomputeMs) + " grid";
  return s;
}

std::string errorText(const LightingMeasurement& m) {
  std::string s = fmt("%.1f dB", m.psnrDb) + fmt(", SSIM %.3f", m.ssim);
  if (m.lighting == Lighting::Cinematic) s += " at " + std::to_string(m.samples) + " spp";
  return s;
}

}  // namespace

SampleLightingFigures parseSampleLightingFigures(const std::string& json,
                                                 const std::string& origin) {
  SampleLightingFigures out;
  try {
    nlohmann::json j = nlohmann::json::parse(json);
    out.on = j.at("on").get<std::string>();
    for (const auto& m : j.at("models")) {
      LightingMeasurement r;
      r.lighting = parseLighting(m.at("lighting").get<std::string>());
      r.width = m.at("width").get<int>();
      r.height = m.at("height").get<int>();
      r.msPerFrame = m.at("ms_per_frame").get<double>();
      r.precomputeMs = m.value("precompute_ms", 0.0);
      r.psnrDb = m.at("psnr_db").get<double>();
      r.ssim = m.at("ssim").get<double>();
      r.samples = m.value("samples", 0);
      r.referenceSamples = m.value("reference_samples", 0);
      r.referenceStdError = m.value("reference_std_error", 0.0);
      r.reference = m.at("reference").get<std::string>();
      out.models.push_back(r);
    }
  } catch (const nlohmann::json::exception& e) {
    throw inputError(origin +
                     ": not the lighting figures' JSON (on, models[lighting, width, "
                     "height, ms_per_frame, psnr_db, ssim, reference]): " +
                     e.what());
  }
  return out;
}

const SampleLightingFigures& builtinSampleLightingFigures() {
  static const SampleLightingFigures f = [] {
    const auto& files = embeddedLightingFigures();
    auto it = files.find("sample-ct.json");
    if (it == files.end()) return SampleLightingFigures{};
    return parseSampleLightingFigures(std::string(it->second), "resources/lighting/sample-ct.json");
  }();
  return f;
}

LightingFigures::LightingFigures() : LightingFigures(builtinSampleLightingFigures()) {}

LightingFigures::LightingFigures(SampleLightingFigures sample) : sample_(std::move(sample)) {}

void LightingFigures::recordFrame(const RenderParams& p, const FrameStats& s, bool interactive) {
  if (interactive || !p.shading || p.mode == Mode::Mip) return;  // not a lit frame's cost
  Seen& seen = seen_[p.lighting];
  if (seen.width != p.width || seen.height != p.height) seen = Seen{{}, 0.0, p.width, p.height};
  seen.frameMs.push_back(std::max(0.0, s.totalMs - s.lightingMs));
  if (seen.frameMs.size() > kFrames) seen.frameMs.pop_front();
  if (s.lightingMs > 0.0) seen.precomputeMs = s.lightingMs;
  changed.notify();
}

void LightingFigures::setMeasured(const std::vector<LightingMeasurement>& m) {
  for (const LightingMeasurement& r : m) measured_[r.lighting] = r;
  measuring_ = false;
  changed.notify();
}

void LightingFigures::setMeasuring(bool on) {
  measuring_ = on;
  changed.notify();
}

void LightingFigures::clear() {
  seen_.clear();
  measured_.clear();
  measuring_ = false;
  changed.notify();
}

std::vector<LightingFigures::Row> LightingFigures::rows() const {
  std::vector<Row> out;
  for (Lighting l : kModels) {
    Row r{l, modelName(l), "", ""};
    const LightingMeasurement* ref = nullptr;
    if (auto m = measured_.find(l); m != measured_.end()) {
      ref = &m->second;
    } else if (measured_.empty()) {
      for (const LightingMeasurement& s : sample_.models)
        if (s.lighting == l) ref = &s;
    }
    auto seen = seen_.find(l);
    if (seen != seen_.end() && !seen->second.frameMs.empty()) {
      std::vector<double> v(seen->second.frameMs.begin(), seen->second.frameMs.end());
      // The grid's build is seen only when it happened; else the measurement's.
      double pre = seen->second.precomputeMs > 0.0 ? seen->second.precomputeMs
                                                   : (ref ? ref->precomputeMs : 0.0);
      r.cost = costText(l, median(v), pre);
    } else if (ref) {
      r.cost =
          costText(l, ref->msPerFrame, ref->precomputeMs) + " at " + size(ref->width, ref->height);
    }
    if (ref) r.error = errorText(*ref);
    out.push_back(r);
  }
  return out;
}

std::string LightingFigures::text(Lighting current) const {
  std::string s;
  for (const Row& r : rows()) {
    if (r.lighting != current) continue;
    s = r.cost.empty() ? "No frame yet" : r.cost;
    if (!r.error.empty()) s += " \u00b7 " + r.error;
  }
  s += "\n";
  if (measuring_)
    s += "Measuring on this view\u2026";
  else if (!measured_.empty())
    s += "dB: this view vs the Monte Carlo reference";
  else if (!sample_.models.empty())
    s += "Measured on the sample CT, not on this scene";
  else
    s += "Not measured on this scene";
  return s;
}

std::string LightingFigures::tooltip() const {
  std::string s;
  for (const Row& r : rows()) {
    s += r.name;
    s += ": " + (r.cost.empty() ? std::string("no frame yet") : r.cost);
    if (!r.error.empty()) s += " \u00b7 " + r.error;
    s += '\n';
  }
  s += "Cost: the median of this scene's last still frames with each model (ms per frame, "
       "the light grid's build apart), else the measurement's frames at their size. Error: "
       "PSNR and SSIM of the model's frame against its reference.";
  const std::vector<LightingMeasurement>* list = nullptr;
  std::vector<LightingMeasurement> mine;
  if (!measured_.empty()) {
    for (const auto& [l, m] : measured_) mine.push_back(m);
    list = &mine;
    s += "\nMeasured on this view:";
  } else if (!sample_.models.empty()) {
    list = &sample_.models;
    s += "\nMeasured on " + sample_.on + " (not this scene):";
  }
  if (list)
    for (const LightingMeasurement& m : *list) {
      // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on "\n" + std::string.
      s += '\n';
      s += modelName(m.lighting);
      s += " (" + size(m.width, m.height) + "): against " + m.reference;
    }
  return s;
}

}  // namespace voxray
