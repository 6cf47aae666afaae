#pragma once
// IceT's half of voxray-mpi: each rank's part image (MultiDeviceRenderer::renderParts, one
// range) composited by IceT across the ranks, the image on rank 0.
//   dvr: ICET_COMPOSITE_MODE_BLEND, premultiplied float RGBA "over", ordered front to back
//        (ICET_ORDERED_COMPOSITE, icetCompositeOrder by the parts' visibility keys: one order
//        serves every pixel of z slabs, multi_device.h);
//   iso: ICET_COMPOSITE_MODE_Z_BUFFER with the hit's sample index as the depth (index * 2^-24:
//        exact in a float, so the nearest hit wins as in the host's composite);
//   mip: the same z-buffer with depth (1 - value) / 2 (IceT has no max mode: the largest
//        value is the nearest depth), depth 1 (IceT's empty) where the ray missed the clip box.
// Each rank gives IceT its slab's projection as bounds (slab_bounds.h), so IceT blends and
// sends only the pixels a slab can cover. ICET_COMPOSITE_ONE_BUFFER: only the colour comes back.
// Rank 0 adds the background and rounds as the kernels' to_rgba8.
//
// Against the host's composite (the same parts, compositeParts) the difference is float
// rounding of "over" associated differently by IceT's tree, and dvr's early termination,
// which IceT does not stop at: the parts behind the point where the opacity reached
// earlyTermination add at most 1 - earlyTermination per channel (multi_device.h).
// IcetColour::Bytes composites 8-bit premultiplied colour instead of float (a quarter of the
// bytes to blend and send): each part is rounded once to 8 bits and IceT's byte "over" rounds
// once per blend, so N ranks may differ from the float composite by up to N levels.
#include <mpi.h>

#include <optional>
#include <string>
#include <vector>

#include "slab_bounds.h"
#include "voxray/engine/multi_device.h"
#include "voxray/io/image.h"

namespace voxray::mpi {

enum class IcetColour { Floats, Bytes };

struct IcetFrameStats {
  double frameMs = 0.0;      // this rank: icetDrawFrame's wall time (render and composite)
  double renderMs = 0.0;     // this rank: its part in the draw callback (kernel and readback)
  double copyMs = 0.0;       // this rank: the part into IceT's image (in the draw callback)
  double compositeMs = 0.0;  // ICET_COMPOSITE_TIME
  double compressMs = 0.0;   // ICET_COMPRESS_TIME (part of the composite)
  double blendMs = 0.0;      // ICET_BLEND_TIME (part of the composite)
  double collectMs = 0.0;    // ICET_COLLECT_TIME: the pieces to rank 0
  double icetTotalMs = 0.0;  // ICET_TOTAL_DRAW_TIME
};

class IcetCompositor {
 public:
  explicit IcetCompositor(MPI_Comm comm);
  ~IcetCompositor();
  IcetCompositor(const IcetCompositor&) = delete;
  IcetCompositor& operator=(const IcetCompositor&) = delete;

  // Collective. The frame P: this rank's one part from RENDERER in IceT's draw callback,
  // composited in the order RANKORDER (front to back, dvr). OUT (rank 0): the image. A part
  // that fails is drawn empty and its message returned in *ERROR on its rank; the frame
  // still completes on every rank, so the caller can agree on the outcome (rank_agreement.h).
  // BOUNDS: where this rank's part can show (slabBoundsNdc; none: the whole image).
  void drawFrame(MultiDeviceRenderer& renderer, const RenderParams& p,
                 const std::vector<int>& rankOrder, const std::optional<NdcBox>& bounds,
                 IcetColour colour, Image* out, IcetFrameStats* stats, std::string* error);

 private:
  MPI_Comm comm_;
  void* communicator_ = nullptr;  // IceTCommunicator
  void* context_ = nullptr;       // IceTContext
};

}  // namespace voxray::mpi
