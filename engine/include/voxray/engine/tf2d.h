#pragma once
// The two-dimensional transfer function (issue 35; Kniss, Kindlmann and Hansen, "Multidimensional
// transfer functions for interactive volume rendering", 2002): colour and opacity over (value in
// HU, gradient magnitude in HU/mm), so that a boundary (high |gradient|) shows while a tissue of
// the same HU (low |gradient|) stays clear. Shaped by rectangles and triangles (Kniss' classic
// widgets) with a colour, a peak opacity and a soft edge; rasterised to a table (Tf2dTable) the
// kernels and the reference renderer read bilinearly. In dvr it REPLACES the 1D table's colour
// and opacity (and the gradient-opacity curve): the 2D function is the whole classification.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/transfer_function.h"

namespace voxray {

struct Volume;

enum class Tf2dShape { Rectangle, Triangle };

struct Tf2dPrimitive {
  Tf2dShape shape = Tf2dShape::Rectangle;
  // Rectangle: HU [hu0, hu1] x |gradient| [g0, g1]. Triangle: its apex at the middle of
  // [hu0, hu1] at |gradient| 0, widening linearly to [hu0, hu1] at g1 (a boundary between two
  // materials arcs up from |gradient| 0 at either), cut to |gradient| [g0, g1].
  double hu0 = 0.0, hu1 = 0.0;
  double g0 = 0.0, g1 = 0.0;  // HU/mm, 0 <= g0 < g1
  glm::dvec3 rgb{1.0};        // 0 ... 1
  double opacity = 1.0;       // the peak, 0 ... 1, per unit distance as the 1D table's
  // The soft edge: the outer fraction (0 ... 1) of each half-extent over which the opacity falls
  // linearly to 0 at the border, along both axes. 0: a hard edge; 1: a tent.
  double soft = 0.0;
  bool operator==(const Tf2dPrimitive&) const = default;
};

struct Tf2d {
  std::vector<Tf2dPrimitive> primitives;  // empty: no 2D transfer function
  // The table's gradient axis runs 0 ... gradientMax HU/mm (larger |gradient| reads the top
  // row); 0: the primitives' highest g1.
  double gradientMax = 0.0;
  bool empty() const { return primitives.empty(); }
  bool operator==(const Tf2d&) const = default;
};

// A file or a flag may give this many primitives at most (an editor makes a handful; each costs
// a pass over the table when it is baked).
inline constexpr size_t kMaxTf2dPrimitives = 256;

// Throws Error (Input) naming ORIGIN and the field (e.g. "tf2d primitive 3: hu1"): a count
// over kMaxTf2dPrimitives, a value that is not finite, hu1 <= hu0, a negative g0, g1 <= g0,
// a colour, opacity or soft edge outside 0 ... 1, a negative gradientMax.
void validate(const Tf2d& tf, const std::string& origin);

// One primitive's opacity at (hu, |gradient| g), 0 ... its peak.
double primitiveOpacity(const Tf2dPrimitive& p, double hu, double g);
// The function at (hu, g): opacity 1 - prod(1 - a_i) (overlaps add up as layers of absorber,
// whatever their order), colour the opacity-weighted mean of the primitives' colours (black
// where nothing shows).
glm::dvec4 tf2dAt(const Tf2d& tf, double hu, double g);
// The gradient axis' top (gradientMax, else the highest g1).
double tf2dGradientMax(const Tf2d& tf);

// The table as the kernels read it (kernels/tf2d_table.h): VOXRAY_TF2D_VALUES columns over
// stored values and VOXRAY_TF2D_GRADIENTS rows over |gradient| in stored units per mm, row-major
// (row j, column i at j * columns + i), bilinear between entries, clamped at the edges. The value
// axis spans the primitives' HU extent and one empty column either side, so values outside it
// read 0; the gradient axis 0 ... tf2dGradientMax.
struct Tf2dTable {
  double storedLo = 0.0;        // the stored value of column 0
  double perStored = 1.0;       // columns per stored unit
  double perStoredPerMm = 1.0;  // rows per stored unit / mm of |gradient|
  std::vector<glm::vec4> rgba;  // empty: off
  int columns() const;
  int rows() const;
  bool empty() const { return rgba.empty(); }
  // Bilinear, clamped; the reference renderer uses this.
  glm::dvec4 lookup(double stored, double storedPerMm) const;
};
// TF on V's stored values (slope and intercept); empty when TF is.
Tf2dTable bakeTf2dTable(const Tf2d& tf, const Volume& v);

// The 2D table seen along value alone, for what reads the 1D table (empty-space skipping, the
// kernels' test whether a sample shows at all, the light grid): into LUT (its entries and their
// stored values kept), each entry's opacity the table's largest over every row and over the
// columns that entry's interpolation span [entry - 1, entry + 1] reaches, colour from that same
// entry. So lut.lookup(v) > 0 wherever table.lookup(v, g) > 0 for some g: a macro cell is empty
// only if the 2D table is 0 over its values for every gradient.
void reduceTf2dToLut(const Tf2dTable& table, Lut& lut);

// The flag's and session's text: "rect:HU0,HU1,G0,G1,R,G,B,A[,SOFT];tri:...;gmax:G" (gmax
// optional). Throws Error (Input) naming the field.
Tf2d parseTf2d(const std::string& text);
std::string formatTf2d(const Tf2d& tf);

}  // namespace voxray
