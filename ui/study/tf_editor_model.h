#pragma once
// The transfer function the user shapes in the editor (issue 35): a VolumeProperty, its two
// lists of points edited one at a time, each edit rendered at once (the view's table becomes
// the property's) and undoable. A drag is one undo step (beginGesture ... endGesture). The
// table edited is the volume's, or a segment's own (RenderParams::segmentTfs; setTarget).
#include <cstdint>
#include <functional>
#include <vector>

#include "no_qt.h"
#include "notifier.h"
#include "render_state_model.h"
#include "tf2d_edit.h"
#include "voxray/engine/volume_property.h"

namespace voxray {

class TfEditorModel {
 public:
  // Follows RENDER: a preset or table chosen elsewhere (the panel, a session) while dvr
  // shows becomes the property being edited (takeFromView).
  explicit TfEditorModel(RenderStateModel& render);
  ~TfEditorModel();
  TfEditorModel(const TfEditorModel&) = delete;
  TfEditorModel& operator=(const TfEditorModel&) = delete;

  const VolumeProperty& property() const { return vp_; }

  // Starts from what the 3D view renders now (its preset or table, as volumePropertyOf
  // reads it; in iso or mip, what dvr would show), with an empty history. Does not change
  // the view.
  void takeFromView();
  // Which table the edits go to: 0 the volume's, else segment LABEL's own (its render table
  // becomes RenderParams::segmentTfs[LABEL]; only its colour and opacity lists and curve
  // count). Starts from that table (a segment without one: from the volume's, and undoing
  // back to there gives the segment none again), with an empty history.
  void setTarget(uint8_t label);
  uint8_t target() const { return target_; }

  // A whole property (a file read by readVolumePropertyFile, already validated): one step.
  void setProperty(const VolumeProperty& vp);

  // Point edits. A point stays between its neighbours (the lists stay sorted) and its
  // opacity and colour within 0 ... 1; a list keeps at least one point. Indices are the
  // list's; an add returns the new point's index.
  size_t addOpacityPoint(double hu, double opacity);
  void moveOpacityPoint(size_t i, double hu, double opacity);
  void removeOpacityPoint(size_t i);
  size_t addColorPoint(double hu);  // with the colour the curve has there
  void moveColorPoint(size_t i, double hu);
  void setPointColor(size_t i, glm::dvec3 rgb);
  void removeColorPoint(size_t i);
  void setCurve(TfCurve curve);
  void setUnitDistance(double mm);  // 0 = one voxel

  // The 2D transfer function's primitives (tf2d.h), in histogram coordinates (HU, HU/mm).
  // Each is one undo step (or part of a gesture); the view's RenderParams::tf2d follows.
  // An add returns the new primitive's index (the last: drawn on top). AXIS_TOP, the
  // editor's gradient axis, becomes the table's gradientMax when the first primitive comes,
  // so that what is drawn at the axis' top row is what the table's top row does.
  size_t addTf2dPrimitive(const Tf2dPrimitive& p, double axisTop = 0.0);
  void moveTf2dPrimitive(size_t i, double dHu, double dG);  // by a delta
  void resizeTf2dPrimitive(size_t i, Tf2dPart corner, double hu, double g);
  // Extents as typed (HU0 < HU1 and 0 <= G0 < G1 kept at their minimum extents).
  void setTf2dExtent(size_t i, double hu0, double hu1, double g0, double g1);
  void setTf2dColor(size_t i, glm::dvec3 rgb);
  void setTf2dOpacity(size_t i, double opacity);
  void setTf2dSoft(size_t i, double soft);
  void removeTf2dPrimitive(size_t i);

  // Every edit between the two is one undo step (a drag). Unbalanced ends do nothing.
  void beginGesture();
  void endGesture();
  bool canUndo() const { return !undo_.empty(); }
  bool canRedo() const { return !redo_.empty(); }
  void undo();
  void redo();

  Notifier<> changed;  // the property changed (an edit, an undo, takeFromView)

 private:
  void edit(const std::function<void(VolumeProperty&)>& change);
  void show();  // the property onto the render state

  void viewChanged(unsigned what);
  // The volume's table as dvr shows it (the editor's own lists where the view still has them).
  VolumeProperty volumeProperty() const;
  // Segment target: what segmentTfs should hold for it now (none at the start of a history
  // that began without one).
  bool segmentOwnsTable() const { return startedOwn_ || !undo_.empty(); }

  RenderStateModel& render_;
  int listener_ = 0;
  uint8_t target_ = 0;       // 0: the volume's table; else this segment's own
  bool startedOwn_ = false;  // segment target: it had its own table when the history began
  bool showing_ = false;     // our own edit reaching the render state
  VolumeProperty vp_;
  std::vector<VolumeProperty> undo_, redo_;
  int gesture_ = 0;
  bool gestureRecorded_ = false;
};

}  // namespace voxray
