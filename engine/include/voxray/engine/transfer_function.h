#pragma once
// Piecewise-linear colour and opacity over HU, and the presets stored in resources/.
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace voxray {

struct Volume;
struct ValueRange;

struct ControlPoint {
  double hu;
  glm::dvec4 rgba;  // colour 0..1, opacity 0..1 per reference step (one voxel)
  bool operator==(const ControlPoint&) const = default;
};

struct TransferFunction {
  std::vector<ControlPoint> points;  // sorted by hu; coincident points make a step
  // Colour and opacity at hu: linear between points, constant beyond the ends.
  glm::dvec4 evaluate(double hu) const;
};

// A lookup table over the stored values [storedMin, storedMax] of a volume, as the
// kernels read it: entry k holds the TF at stored value storedMin + k / scale.
struct Lut {
  double storedMin = 0.0;
  double scale = 1.0;           // entries per stored unit
  std::vector<glm::vec4> rgba;  // float, as uploaded to the device
  // Linear interpolation between entries, clamped; the reference renderer uses this too.
  glm::dvec4 lookup(double stored) const;
};
Lut bakeLut(const TransferFunction& tf, const Volume& v, int maxEntries = 4096);
// The same with V's storedRange given (it costs a pass over the volume).
Lut bakeLut(const TransferFunction& tf, const Volume& v, const ValueRange& range,
            int maxEntries = 4096);

// The gradient opacity as the kernels read it (RenderParams::gradientOpacity, issue 35): equally
// spaced factors over |gradient| 0 ... the last point's, in stored units per mm (the volume's
// slope folded in), linear between entries, the last beyond. The reference renderer uses it too.
struct GradientTable {
  double scale = 0.0;                       // entries per stored unit / mm
  std::vector<float> factor;                // empty: off
  double lookup(double storedPerMm) const;  // 1 when off
};
// POINTS: (|gradient| in HU/mm, factor), sorted; SLOPE: HU per stored unit. Empty when POINTS is.
GradientTable bakeGradientTable(const std::vector<glm::dvec2>& points, double slope);

struct Preset {
  std::string name;
  std::string description;
  std::string mode;     // iso, dvr or mip: the mode it was made for
  TransferFunction tf;  // dvr colours; for iso, the surface colour at the hit
  double isoLo = 0.0, isoHi = 0.0;
  double windowWidth = 0.0, windowLevel = 0.0;
};

// Presets from resources/presets/*.json, embedded in the binary at build time.
const std::vector<Preset>& builtinPresets();
// By name, case-insensitive; throws Error (Input) listing the known names.
const Preset& findPreset(const std::string& name);
struct RenderParams;
// Selects the preset (dropping a custom table and the preset shift) and takes its mode, iso
// range and window where it has them.
void applyPreset(RenderParams& p, const Preset& preset);

// Parses one preset from JSON text; throws Error (Input) saying what is wrong.
Preset parsePreset(const std::string& json, const std::string& origin);

}  // namespace voxray
