#pragma once
// Where a rank's z slab can appear in the image, for IceT: IceT composites only the pixels
// inside the projections of the ranks' bounds (ICET_CONTAINED_VIEWPORT), so a rank whose slab
// covers a third of a 4K image blends, sends and receives a third of it.
#include <optional>

#include "voxray/engine/multi_device.h"  // PartRange
#include "voxray/engine/render_params.h"

namespace voxray {
struct Volume;
}

namespace voxray::mpi {

// A box in normalised device coordinates: x and y run -1 ... 1 across the image (x right,
// y up; pixel centres where ViewGeometry::ray puts them).
struct NdcBox {
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
};

// The box around the projections of the 8 corners of the slab RANGE of VOLUME (its slices
// first ... end - 1 and one slice beyond either side, cut to the volume's box) in the frame P.
// IceT is given identity matrices, so this is its bounds as it is. None when the slab reaches
// behind a perspective eye (its projection is unbounded): then the rank covers the whole image.
std::optional<NdcBox> slabBoundsNdc(const Volume& volume, const RenderParams& p,
                                    const PartRange& range);

}  // namespace voxray::mpi
