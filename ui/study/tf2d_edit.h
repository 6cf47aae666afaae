#pragma once
// The 2D transfer-function editor's geometry (issue 35), in histogram coordinates (HU,
// |gradient| HU/mm): which primitive or handle is under the mouse, and a primitive moved or
// resized the way a drag does it. Pure functions; TfEditorModel makes them undo steps.
#include <optional>

#include "no_qt.h"
#include "voxray/engine/tf2d.h"

namespace voxray {

// The parts a drag can hold: the body (moves it) or a corner of its box (resizes it). A
// triangle's box is [hu0, hu1] x [g0, g1] too; its handles are that box's corners.
enum class Tf2dPart { Body, LowHuLowG, HighHuLowG, LowHuHighG, HighHuHighG };

struct Tf2dHit {
  size_t index = 0;
  Tf2dPart part = Tf2dPart::Body;
  bool operator==(const Tf2dHit&) const = default;
};

// Whether (HU, G) lies inside P's shape (a triangle: under its two slanted sides).
bool tf2dContains(const Tf2dPrimitive& p, double hu, double g);
// The primitive at (HU, G): handles first (within HU_TOL and G_TOL, a few pixels' worth),
// then bodies; the last primitive (drawn on top) wins.
std::optional<Tf2dHit> tf2dHitTest(const Tf2d& tf, double hu, double g, double huTol, double gTol);

// The smallest extents a resize leaves (a primitive never folds over).
inline constexpr double kTf2dMinHu = 1.0;
inline constexpr double kTf2dMinG = 0.5;

// P shifted by (DHU, DG); |gradient| stays >= 0 (the whole shape stops at the axis).
Tf2dPrimitive tf2dMoved(Tf2dPrimitive p, double dHu, double dG);
// P with PART's corner at (HU, G), the opposite corner kept, extents at least the minimum.
Tf2dPrimitive tf2dResized(Tf2dPrimitive p, Tf2dPart part, double hu, double g);

}  // namespace voxray
