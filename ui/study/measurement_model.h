#pragma once
// The user's measurements (distance, angle, ellipse and rectangle ROI) as data: points in
// voxel coordinates of the open volume (continuous, centres at integers), so that the views
// draw them, the panel lists them and the session stores them, while the maths stays in
// voxray/engine/measure.h. Widgets only forward gestures here.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "notifier.h"
#include "slice_geometry.h"
#include "voxray/engine/measure.h"
#include "voxray/engine/roi_peak.h"

namespace voxray {
struct Volume;
}

namespace voxray {

enum class MeasureKind { Distance, Angle, Ellipse, Rect };
const char* toString(MeasureKind k);
// Points a finished measurement of KIND has: 2, 3 (A, vertex, C), 2 (opposite corners).
int pointCount(MeasureKind k);

struct Measurement {
  int id = 0;
  MeasureKind kind = MeasureKind::Distance;
  std::vector<glm::dvec3> points;  // voxel positions
  // The voxel axis across the view it was drawn in (ROIs lie in that index plane); -1 for a
  // distance picked in 3D, which belongs to no slice view.
  int normalAxis = 2;
};

// The tool a left drag in a slice view uses; None moves the crosshair.
// Text and Arrow place annotations (annotation_model.h), not measurements.
enum class MeasureTool { None, Distance, Angle, Ellipse, Rect, Text, Arrow };

class MeasurementModel {
 public:
  const std::vector<Measurement>& items() const { return items_; }
  const Measurement* find(int id) const;
  // Adds a measurement and selects it; returns its id.
  int add(MeasureKind kind, std::vector<glm::dvec3> points, int normalAxis);
  // Moves point INDEX of measurement ID (a handle drag); ROI corners keep their plane.
  void movePoint(int id, int index, const glm::dvec3& voxel);
  void remove(int id);
  void clear();
  int selected() const { return selected_; }  // 0: none
  void select(int id);

  MeasureTool tool() const { return tool_; }
  void setTool(MeasureTool t);
  // The first point of a distance being picked in the 3D view (shown in every view).
  const std::optional<glm::dvec3>& pendingPick() const { return pendingPick_; }
  // A surface point picked in 3D: the first is kept pending, the second completes a
  // distance (normal axis -1) and returns its id.
  std::optional<int> addPick(const glm::dvec3& voxel);
  void cancelPick();
  // Burn measurements into exported images (off by default: the user's choice).
  bool showInExports() const { return showInExports_; }
  void setShowInExports(bool on);

  Notifier<> changed;

 private:
  Measurement* findMutable(int id);
  std::vector<Measurement> items_;
  int nextId_ = 1, selected_ = 0;
  MeasureTool tool_ = MeasureTool::None;
  bool showInExports_ = false;
  std::optional<glm::dvec3> pendingPick_;
};

// Whether a slice view (AXES at SLICE) shows measurement M whole: an ROI drawn in that plane,
// or a distance or angle whose points all lie within half a voxel of the slice.
bool shownOnSlice(const Measurement& m, const SliceAxes& axes, int slice);
// Whether a single point lies within half a voxel of the slice (3D picks are marked there).
bool pointOnSlice(const glm::dvec3& voxel, const SliceAxes& axes, int slice);
// A voxel position moved into the volume's box: tools never leave the volume.
glm::dvec3 clampToVolume(const glm::dvec3& voxel, const glm::ivec3& dims);

// The numbers of one measurement as text: "42.3 mm", "87.5°", or for an ROI
// "mean 12.3 SD 4.5 min 0 max 30 HU, 120.4 mm², 97 px". Anything undefined (an angle with a
// zero-length arm, an ROI without a pixel) reads "—"; never NaN.
std::string measurementText(const Volume& v, const Measurement& m);
// The ROI statistics of an ellipse or rectangle measurement.
RoiStats measurementStats(const Volume& v, const Measurement& m);
// The ROI's peak: the best 1 cm³ sphere centred in it (PERCIST; rules in roi_peak.h).
RoiPeak measurementPeak(const Volume& v, const Measurement& m);

}  // namespace voxray
