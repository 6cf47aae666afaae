#pragma once
// The lighting models' cost and error on the current scene, as the Light group shows them
// beside its Model combo (issue 15; the quality presets show theirs the same way). Cost:
// the still frames this scene actually rendered with each model (FrameStats), else the
// last "Measure on this view" (lighting_measure.h). Error: that measurement. Until
// measured, the figures measured on the sample CT (resources/lighting/sample-ct.json, remade
// by the LightingMeasure.DISABLED_PrintSampleCtFigures test), said to be so. A new volume
// clears what was seen and measured.
#include <deque>
#include <map>
#include <string>
#include <vector>

#include "lighting_measure.h"
#include "no_qt.h"
#include "notifier.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/render_params.h"

namespace voxray {

// The sample CT's figures: built in (embedded), or parsed from JSON (tests). Throws Error
// (Input) naming ORIGIN and what is wrong.
struct SampleLightingFigures {
  std::string on;  // what and where they were measured
  std::vector<LightingMeasurement> models;
};
SampleLightingFigures parseSampleLightingFigures(const std::string& json,
                                                 const std::string& origin);
const SampleLightingFigures& builtinSampleLightingFigures();

class LightingFigures {
 public:
  // Frames kept per model for the median.
  static constexpr size_t kFrames = 9;

  LightingFigures();
  explicit LightingFigures(SampleLightingFigures sample);

  // A view frame arrived. Drag frames (smaller, coarser) are not the model's cost; a
  // cinematic frame is one pass of samples.
  void recordFrame(const RenderParams& p, const FrameStats& s, bool interactive);
  void setMeasured(const std::vector<LightingMeasurement>& m);
  void setMeasuring(bool on);
  void clear();  // a new volume: nothing seen or measured on it yet

  struct Row {
    Lighting lighting = Lighting::Phong;
    std::string name;   // "Shadows"
    std::string cost;   // "41.2 ms + 96 ms grid" ("" when unknown)
    std::string error;  // "37.5 dB, SSIM 0.991" ("" when unknown)
  };
  std::vector<Row> rows() const;  // phong, shadows, ao, cinematic
  // The label beside the Model combo: the current model's row, then where its figures
  // come from.
  std::string text(Lighting current) const;
  std::string tooltip() const;  // every model's row, then the references and sizes in full
  bool measured() const { return !measured_.empty(); }
  bool measuring() const { return measuring_; }

  Notifier<> changed;

 private:
  struct Seen {
    std::deque<double> frameMs;  // the frame without the grid's build
    double precomputeMs = 0.0;   // the last build seen
    int width = 0, height = 0;
  };
  SampleLightingFigures sample_;
  std::map<Lighting, Seen> seen_;
  std::map<Lighting, LightingMeasurement> measured_;
  bool measuring_ = false;
};

}  // namespace voxray
