#pragma once
// Owns the OpenCL context and the Raycaster on one thread of its own (the Raycaster is not
// thread-safe) so that rendering never blocks the UI. Requests do not queue up: a new
// request replaces one that has not started, so a fast drag renders only the latest
// camera. A sharp view frame may come in bands of rows (refine_bands.h), each posted as it
// finishes over the last view frame; a new view request or volume abandons the bands left
// (an export in between lets them continue after it). Runs as a BackgroundTask: results and errors
// arrive through its Post (the scheduler's GUI thread).
#include <condition_variable>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "background_task.h"
#include "no_qt.h"
#include "refine_bands.h"
#include "time_series.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/out_of_core.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/render_params.h"
#include "voxray/io/image.h"
#include "voxray/io/segment_edit.h"
#include "voxray/io/segmentation.h"
#include "voxray/io/volume.h"

namespace voxray {

struct Frame {
  Image image;
  FrameStats stats;
  RenderParams params;
  bool interactive = false;     // a cheap frame rendered during a drag
  int tag = 0;                  // the caller's label (0: the view; other values: exports)
  std::vector<glm::vec4> hits;  // each pixel's iso or dvr hit, when asked for (renderWithHits)
  // A banded frame (requestBands): bands rendered so far of `bands`; 0 of 0 for a whole
  // frame. Rows of bands not yet rendered show the last view frame, scaled to this size.
  int bandsDone = 0, bands = 0;
  RowBand band;  // the band this frame added
  // The volume it shows (identity only, never read): a 4D series' frames say their time point.
  const Volume* volume = nullptr;
  // A coarse level's preview of a new study (issue 38): rendered from a 4x (or 8x) box-mean
  // level of the volume, in its geometry, before the full volume is uploaded; the frame of the
  // full volume follows. Show it, and say "coarse preview" while it shows.
  bool coarse = false;
  // Out of core (issue 38 part 2, out_of_core_view.h): a study larger than the device (or the
  // GPU memory budget) drawn part by part. A drag's frame is a preview (the parts on the
  // device at full resolution, the others from a coarse level); the still frame converges.
  // The view says RESOLUTIONNOTE while it shows ("" at full resolution) and LIMITSNOTE while
  // something the out-of-core renderer does not draw is off ("" when nothing is).
  bool outOfCore = false;
  OutOfCoreStats outOfCoreStats;
  std::string resolutionNote, limitsNote;
};

// How the worker decides on out of core (chooseOutOfCore).
struct OutOfCoreSettings {
  size_t budgetBytes = 0;     // the "GPU memory budget" preference; 0: automatic
  int partSlices = 0;         // OutOfCoreOptions::partSlices (0: about 8 parts fit)
  int faultDeviceParts = -1;  // OutOfCoreOptions::faultDeviceParts (tests)
  bool operator==(const OutOfCoreSettings&) const = default;
};

// A new study of at least this many bytes is previewed from a coarse level before its upload
// (a 512 x 512 x 128 CT; smaller volumes upload about as fast as the preview would render).
constexpr size_t kCoarsePreviewBytes = size_t(64) << 20;
// What the workstation's status bar says while a coarse frame shows.
inline constexpr const char* kCoarsePreviewText = "coarse preview: the full volume is uploading…";

struct RenderCallbacks {
  std::function<void(std::shared_ptr<const Frame>)> frame;
  // After a failed context creation, upload or render. VOLUME_REJECTED: the last volume
  // given to setVolume could not be uploaded; the previous one is still rendered.
  std::function<void(const std::string& message, bool volumeRejected)> error;
  std::function<void(const std::string& deviceName)> deviceReady;
  // Kernel variants that prepare() builds in the background: LEFT still to build (0: done).
  std::function<void(int left)> preparing;
  // A frame of requestBackground, with its tag.
  std::function<void(std::shared_ptr<const Frame>)> background;
};

class RenderWorker {
 public:
  // DEVICE: a ClContext selector ("" = $VOXRAY_DEVICE or auto). POST: where callbacks run
  // (BackgroundTask::Post; none: on the render thread).
  RenderWorker(std::string device, RenderCallbacks callbacks, BackgroundTask::Post post = {});
  ~RenderWorker();  // waits for the frame in progress
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  // The volume to render. SAMESERIES: another time point of the series shown (a 4D
  // series): volumes of the series uploaded before stay on the device within
  // residencyBudget (time_series.h), so that switching back needs no upload; otherwise
  // (another study) every uploaded volume is released first.
  void setVolume(std::shared_ptr<const Volume> volume, bool sameSeries = false);
  // How a study is put on the device: in core, or out of core when it does not fit the device
  // or SETTINGS' budget (a 4D series' time points stay in core). A change that moves the study
  // shown between the two (or changes its budget) opens it again.
  void setOutOfCore(OutOfCoreSettings settings);
  // The time points of SERIES not uploaded yet, uploaded one at a time while no frame or
  // volume waits, as far as residencyBudget allows, so that switching to them needs no
  // upload (a frame asked for meanwhile waits for one upload at most). A later setVolume of
  // another study drops what is left.
  void preload(VolumeSeries series);
  // The segmentation dvr frames classify by (Raycaster::setSegmentation), a copy the render
  // thread keeps; null: none. A segmentation off the volume's grid is not shown (the next
  // volume's, while it loads, or the last one's).
  void setSegmentation(std::shared_ptr<const Segmentation> whole);
  // An edit of the segmentation set before: its segment list and, unless empty, the new labels
  // of the edited box (only the box travels: a whole copy of a large label map per paint dab
  // took 73 ms, see the README's segment editor figures).
  void updateSegmentation(std::vector<Segment> segments, LabelPatch box);
  // Fused dvr (issue 36, Raycaster::setOverlay): OVERLAY with its table TF classified in the
  // same pass as the volume, on its own grid; null: none. Each time point's raycaster takes
  // it before its next frame.
  void setOverlay(std::shared_ptr<const Volume> overlay, TransferFunction tf);
  // WITHHITS: also each pixel's iso first hit or dvr first opaque point (Frame::hits), for
  // picking in 3D.
  void request(const RenderParams& params, bool interactive, int tag = 0, bool withHits = false);
  // The view's sharp frame in BANDS (in order; empty or one: a whole frame), each band
  // posted as a Frame when it finishes.
  void requestBands(const RenderParams& params, std::vector<RowBand> bands);
  // Low-priority frames (the preset gallery's pictures, tf_gallery.h), each (tag, params):
  // rendered one at a time, in order, only while no view frame, export or volume waits, and
  // posted through RenderCallbacks::background. A new call replaces the frames not yet
  // started (an empty list cancels them).
  void requestBackground(std::vector<std::pair<int, RenderParams>> frames);
  // A frame of VOLUME (the one shown, or a time point on the device) for a caller on another
  // thread (the movie export, issue 40 item 6): rendered on the render thread by the
  // raycaster that holds VOLUME, between the view's frames (ahead of them, as an export), so
  // that no second context uploads the volume again. Blocks until it is rendered; throws what
  // the render throws, Error (Device) when VOLUME is not on the device (another study was
  // opened) or the worker stopped. Never call it on the render thread.
  Image renderOnDevice(const RenderParams& params, const Volume* volume);
  // Builds the kernel variants of PARAMS (frames likely soon: a drag, another mode) on a
  // low-priority thread of their own, in order, so that such a frame does not wait for the
  // compiler (issue 41 item 9: a variant took 2-3 s on PoCL). Frames render meanwhile. A new
  // call replaces the variants not yet started; a new volume keeps them.
  void prepare(std::vector<RenderParams> params);
  // Whether a frame, volume or edit waits or the render thread works on one (a frame it
  // finished is posted before it is idle again). For tests that wait for the frame of the
  // last change however long its kernel takes to build.
  bool busy();

 private:
  void buildLoop(ClContext& ctx);
  void run();
  void reportError(const std::string& message, bool volumeRejected) const;
  // Posts a coarse frame (Frame::coarse) of VOLUME with the pending view's parameters (else
  // LASTVIEW's; neither: nothing), on the render thread, before VOLUME is uploaded.
  void previewCoarse(ClContext& ctx, const Volume& volume,
                     const std::optional<RenderParams>& lastView);
  // The volumes on the device (one, or time points of a 4D series), each kept alive while
  // its raycaster uses it.
  struct Uploaded {
    std::shared_ptr<const Volume> volume;
    std::unique_ptr<Raycaster> raycaster;
  };
  // Makes NEXT, a time point of the series shown, the one SHOWN renders: from UPLOADED when
  // it is there, else uploaded, releasing what RESIDENCY evicts. A failed upload keeps SHOWN.
  void selectTimePoint(ClContext& ctx, const std::shared_ptr<const Volume>& next,
                       std::vector<Uploaded>& uploaded, VolumeResidency& residency,
                       Raycaster*& shown) const;

  std::string device_;
  RenderCallbacks callbacks_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool working_ = false;  // the render thread took work and has not come back for more
  std::shared_ptr<const Volume> pendingVolume_;
  std::optional<OutOfCoreSettings> pendingOutOfCore_;
  // The study drawn out of core (null renderer: in core).
  struct OutOfCoreShown {
    std::shared_ptr<const Volume> volume;
    std::unique_ptr<SlabSource> source;
    std::unique_ptr<OutOfCoreRenderer> renderer;
    size_t budgetBytes = 0;
  };
  // Opens VOLUME out of core within BUDGET on CTX; throws what the renderer throws.
  static std::unique_ptr<OutOfCoreShown> openOutOfCore(ClContext& ctx,
                                                       std::shared_ptr<const Volume> volume,
                                                       size_t budget,
                                                       const OutOfCoreSettings& settings);
  struct SegmentationUpdate {
    bool replace = false;  // `whole` replaces the copy (null: none)
    std::shared_ptr<const Segmentation> whole;
    bool hasSegments = false;  // `segments` replaces the copy's list
    std::vector<Segment> segments;
    std::vector<LabelPatch> patches;  // in order
  };
  std::optional<SegmentationUpdate> pendingSegmentation_;
  struct OverlayUpdate {
    std::shared_ptr<const Volume> volume;  // null: none
    TransferFunction tf;
  };
  std::optional<OverlayUpdate> pendingOverlay_;
  bool pendingSameSeries_ = false;
  VolumeSeries pendingPreload_;  // time points still to upload ahead, in order
  struct Request {
    RenderParams params;
    bool interactive;
    int tag;
    bool withHits;
    std::vector<RowBand> bands;  // still to render; empty: the whole frame
    int bandsTotal = 0;
    bool background = false;  // of requestBackground
  };
  // Renders REQ's bands into VIEW (the last view frame) until done or a newer view request
  // or volume arrives; what is left goes back as the pending view request unless replaced.
  void renderBands(Raycaster& raycaster, Request req, Image& view, const Volume* volume);
  std::optional<Request> pendingView_;    // latest view frame wins
  std::optional<Request> pendingExport_;  // exports are never replaced by view frames
  std::vector<std::pair<int, RenderParams>> pendingBackground_;  // in order
  struct OnDevice {                                              // a renderOnDevice call waiting
    RenderParams params;
    const Volume* volume = nullptr;
    std::promise<Image> image;
  };
  std::vector<std::shared_ptr<OnDevice>> pendingOnDevice_;  // in order
  std::vector<RenderParams> pendingPrepare_;                // for the render thread: to options
  std::vector<std::string> toBuild_;                        // for the build thread: raycast options
  BackgroundTask task_;                                     // cancelled: the loop ends
};

}  // namespace voxray
