#pragma once
// Which macro cells a dvr transfer function may show in, folded per stored value so that the
// device reads two numbers per cell (kernels/empty_space/classify.cl, classify_dvr) instead of
// placing the cell's min and max on the table in floats (classify's mode 1, the same test).
#include <cstdint>
#include <vector>

namespace voxray {

struct DvrCellBounds {
  int lo = 0;  // the stored value of from[0] and to[0]
  // Per stored value v = lo + i: from[i] counts the non-transparent table entries below the
  // first one a cell whose min is v can interpolate from, to[i] those up to the last one a cell
  // whose max is v can (classify.cl's margin of half a stored unit and one entry). A cell with
  // min a and max b is occupied when to[b - lo] > from[a - lo].
  std::vector<int32_t> from, to;
};

// opaqueBefore[k]: the non-transparent entries below entry k (the table's size + 1 counts);
// storedMin and scale place the table (Lut, as the kernels get them: floats); [lo, hi]: the
// stored values the cells' min/max take.
DvrCellBounds dvrCellBounds(const std::vector<int>& opaqueBefore, float storedMin, float scale,
                            int lo, int hi);

}  // namespace voxray
