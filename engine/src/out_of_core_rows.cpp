// The empty-space cell rows and the value range an out-of-core renderer learns from the slices
// it reads (out_of_core.h: opening reads no full-resolution slice).
#include <algorithm>
#include <string>

#include "macro_cells.h"
#include "out_of_core_impl.h"

namespace voxray {

// The cell rows all of whose voxels lie in slices [FIRST, END) (held at SLICES) and are not
// known yet: made now (on the host, while the device renders), applied at the next frame.
void OutOfCoreRenderer::Impl::learnRows(const int16_t* slices, int first, int end) {
  glm::ivec2 rows = completeCellRows(first, end, geom.dims.z);
  while (rows.x < rows.y && rowKnown[size_t(rows.x)]) ++rows.x;
  while (rows.x < rows.y && rowKnown[size_t(rows.y - 1)]) --rows.y;
  if (rows.x >= rows.y) return;
  std::vector<int16_t> mm = computeMacroCellRows(slices, first, geom.dims, rows);
  for (size_t c = 0; c + 1 < mm.size(); c += 2) {
    knownLo = std::min<int>(knownLo, mm[c]);
    knownHi = std::max<int>(knownHi, mm[c + 1]);
  }
  for (int r = rows.x; r < rows.y; ++r) {
    rowsKnown += !rowKnown[size_t(r)];
    rowKnown[size_t(r)] = 1;
  }
  if (o.emptySpaceSkipping) pendingRows.emplace_back(rows, std::move(mm));
}

// Every row known: the voxels' range, as in core. Else the hint widened to the rows known.
ValueRange OutOfCoreRenderer::Impl::currentRange() const {
  if (rowsKnown == int(rowKnown.size())) return {int16_t(knownLo), int16_t(knownHi)};
  if (rowsKnown == 0) return hint;
  return {int16_t(std::min<int>(hint.min, knownLo)), int16_t(std::max<int>(hint.max, knownHi))};
}

// The learned rows to the device and the range to the tables. True when the range changed.
bool OutOfCoreRenderer::Impl::applyLearned() {
  for (const auto& [rows, mm] : pendingRows) fullSpace.replaceRows(cl, rows, mm.data());
  pendingRows.clear();
  const ValueRange r = currentRange();
  if (rowsKnown == int(rowKnown.size()) && hintStated && note.empty() &&
      (r.min != hint.min || r.max != hint.max))
    note = "the value range the source states (" + std::to_string(hint.min) + " to " +
           std::to_string(hint.max) + ") is not its voxels' (" + std::to_string(r.min) + " to " +
           std::to_string(r.max) + "): the voxels' is used";
  if (r.min == used.min && r.max == used.max) return false;
  used = r;
  full.valueRange = r;
  coarseFrame->valueRange = r;  // the coarse level's colours are the full volume's
  full.setupKey.reset();        // the tables are made again for the new range
  coarseFrame->setupKey.reset();
  return true;
}

}  // namespace voxray
