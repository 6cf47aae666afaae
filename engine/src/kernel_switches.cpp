#include "kernel_switches.h"

#include <cctype>
#include <sstream>
#include <vector>

#include "kernel_params.h"
#include "voxray/engine/kernel_variant.h"

namespace voxray {

namespace {

enum class Kind { FRAME, RUNTIME, BUILD };

struct SwitchEntry {
  const char* name;
  int defaultValue;
  Kind kind;
  const char* labels;
  int KernelSwitches::*field;
};

const std::vector<SwitchEntry>& switchList() {
  static const std::vector<SwitchEntry> list = {
#define VOXRAY_SWITCH(NAME, DEFAULT, KIND, LABELS) \
  {#NAME, DEFAULT, Kind::KIND, LABELS, &KernelSwitches::NAME},
#include "switches.h"
#undef VOXRAY_SWITCH
  };
  return list;
}

// The packets' tuning: a value for 8 lanes and one for 16.
struct TuningEntry {
  const char* name;
  int at8;
  int at16;
};

const std::vector<TuningEntry>& tuningList() {
  static const std::vector<TuningEntry> list = {
#define VOXRAY_SWITCH(NAME, DEFAULT, KIND, LABELS)
#define VOXRAY_TUNING(NAME, AT_8_LANES, AT_16_LANES) {#NAME, AT_8_LANES, AT_16_LANES},
#include "switches.h"
#undef VOXRAY_TUNING
#undef VOXRAY_SWITCH
  };
  return list;
}

// Label `value` of "a|b|c"; "" past the end.
std::string label(const std::string& labels, int value) {
  std::istringstream in(labels);
  std::string item;
  for (int i = 0; std::getline(in, item, '|'); ++i)
    if (i == value) return item;
  return "";
}

}  // namespace

KernelSwitches kernelSwitches(const RenderParams& p) {
  KernelSwitches s;
  s.MODE = int(p.mode);
  s.SHADING = p.shading && p.mode != Mode::Mip;
  s.TF2D = p.mode == Mode::Dvr && !p.tf2d.empty();  // it replaces the gradient opacity
  s.GRADIENT_OPACITY = p.mode == Mode::Dvr && !p.gradientOpacity.empty() && !s.TF2D;
  if (s.SHADING || s.GRADIENT_OPACITY || s.TF2D) s.GRADIENT = int(p.gradient);
  s.INTERP = int(p.interp);
  s.ORTHO = p.camera.projection == Projection::Orthographic;
  if (p.mode == Mode::Dvr) s.OPACITY_CORRECTION = p.opacityCorrection;
  // Long steps rest on opacity correction and on the macro cells' levels (ESS), which read
  // the colour table alone: the gradient opacity would need them per gradient too.
  s.ADAPTIVE = s.OPACITY_CORRECTION && p.adaptiveError > 0.0 && !s.GRADIENT_OPACITY && !s.TF2D;
  s.JITTER = p.jitter;
  if (p.mode == Mode::Iso) s.REFINE_STEPS = p.refine;
  // shadows and ao change the shading only; cinematic is the path tracer's (not a switch).
  if (s.SHADING && (p.lighting == Lighting::Shadows || p.lighting == Lighting::Ao))
    s.LIGHTING = int(p.lighting);
  return s;
}

KernelSwitches kernelSwitches(const RenderParams& p, const KernelFacts& f) {
  KernelSwitches s = kernelSwitches(p);
  s.ESS = f.emptySpaceSkipping;
  s.LABELS = f.labels && p.mode == Mode::Dvr;
  s.SEGMENT_TF = s.LABELS && f.segmentTf && !s.TF2D;
  // The levels live with the macro cells, and read the colour table alone (not the labels).
  // The overlay: fused into dvr's samples, or its maximum over mip's grey (overlay_mip).
  s.OVERLAY = f.overlay && (p.mode == Mode::Dvr || p.mode == Mode::Mip);
  s.SURFACES = f.surfaces && p.mode == Mode::Dvr;
  // Pre-integration classifies segments from the colour table alone (switches.h says which
  // others classify one sample); it replaces the adaptive steps, whose levels assume samples.
  s.PREINT = f.preintegrate && p.mode == Mode::Dvr && !s.TF2D && !s.GRADIENT_OPACITY && !s.LABELS &&
             !s.OVERLAY && !s.SURFACES;
  s.ADAPTIVE = s.ADAPTIVE && s.ESS && !s.LABELS && !s.OVERLAY && !s.PREINT;  // (nor the overlay)
  s.STORAGE_IMAGE = f.storageImage;
  s.SLABS = f.slabs;
  s.COUNT_SAMPLES = f.countSamples;
  s.HIT_OUTPUT = f.hitOutput;
  if (f.packetLanes > 0) {
    s.PACKET = 1;
    s.LANES = f.packetLanes;
    // 8-lane packets only (docs/bench/README.md, session 9): mip marches two per work-item,
    // iso passes empty voxel blocks (their bits ride with the leap distances: ESS).
    if (s.LANES == 8 && p.mode == Mode::Mip) s.MIP_HALVES = 2;
    if (s.LANES == 8 && p.mode == Mode::Iso && s.ESS) s.ISO_BLOCK_TRIES = 4;
  }
  return s;
}

std::string switchOptions(const KernelSwitches& s, bool uber) {
  std::ostringstream o;
  o << "-D VOXRAY_SWITCHES_SET=1";
  for (const SwitchEntry& e : switchList()) {
    bool runtime = e.kind == Kind::RUNTIME || (uber && e.kind == Kind::FRAME);
    o << " -D " << e.name << "=";
    if (runtime)
      o << "P_SWITCH(VOXRAY_SLOT_" << e.name << ")";
    else
      o << s.*e.field;
  }
  if (s.PACKET)
    for (const TuningEntry& t : tuningList())
      o << " -D " << t.name << "=" << (s.LANES == 8 ? t.at8 : t.at16);
  return o.str();
}

void packSwitches(const KernelSwitches& s, RaycastParams& k) {
  const auto& list = switchList();
  for (size_t i = 0; i < list.size(); ++i) k.switches[i / 4].s[i % 4] = s.*list[i].field;
}

std::string variantName(const KernelSwitches& s) {
  std::string out;
  for (const SwitchEntry& e : switchList()) {
    int value = s.*e.field;
    // Only shaded or gradient-opacity frames take a gradient: elsewhere "central" would name
    // nothing measured.
    if (e.field == &KernelSwitches::GRADIENT && !s.SHADING && !s.GRADIENT_OPACITY && !s.TF2D)
      continue;
    std::string part;
    if (*e.labels)
      part = label(e.labels, value);
    else if (value != e.defaultValue)
      part = std::string(e.name) + std::to_string(value);
    for (char& c : part) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (part.empty()) continue;
    out += (out.empty() ? "" : "_") + part;
  }
  return out;
}

std::string kernelVariantName(const RenderParams& p) { return variantName(kernelSwitches(p)); }

}  // namespace voxray
