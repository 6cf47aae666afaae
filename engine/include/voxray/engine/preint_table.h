#pragma once
// Pre-integrated classification (issue 40; Engel, Kraus, Ertl 2001): dvr's transfer function
// integrated along a segment whose value runs linearly from the front sample's to the back
// sample's, for the frame's step, as the kernels read it (kernels/preint_table.h, PREINT). A
// long step then keeps what the table shows between two samples (thin shells, steep ramps)
// instead of aliasing it; the opacity correction to the step is built in.
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/transfer_function.h"

namespace voxray {

struct PreintTable {
  // Row and column 0's stored value and entries per stored unit: the rows and columns fall on
  // entries of the colour table (a whole number of them apart), over the entries where it
  // shows and one transparent entry either side.
  double storedLo = 0.0;
  double perStored = 1.0;
  int entriesPerBin = 1;  // colour-table entries between two rows
  double ratio = 0.0;     // the segment's length over the reference step it was made for
  // Row-major, row the front value and column the back value: the opacity-weighted mean colour
  // and the optical depth in log2 units (opacity 1 - 2^-w). Empty: off.
  std::vector<glm::vec4> rgba;
  // The colour table with each entry's opacity the largest within a row's spacing around it
  // (plus the interpolation's entry): what empty-space skipping reads, so that a macro cell is
  // leapt only where every table entry a segment inside it can read is 0.
  Lut occupancy;
  bool empty() const { return rgba.empty(); }
  static int size();  // rows (= columns): VOXRAY_PREINT_VALUES
  // The opacity of entry (front row i, back column j), as the kernels compute it.
  double alphaAt(int i, int j) const;
  // The kernels' lookup (preint.cl) in double: colour and opacity of a segment `segRatio`
  // times the step long from stored value vf to vb.
  glm::dvec4 lookup(double vf, double vb, double segRatio = 1.0) const;
};

// LUT (opacities per reference step) integrated for segments `ratio` reference steps long
// (1 without opacity correction). O(entries + size()^2): prefix sums of the optical depth and
// of the depth-weighted colour over the colour table, the integral between two values their
// difference.
PreintTable bakePreintTable(const Lut& lut, double ratio);

}  // namespace voxray
