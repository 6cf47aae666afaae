#pragma once
// The frames of a movie and the loop that writes them: a 360-degree orbit of the raycast
// view, or a cine through the slices of one MPR view (axial, coronal or sagittal index
// planes, resampled by samplePlane and shown with a window). Shared by `voxray-cli movie`
// and the workstation's File > Export movie.
#include <atomic>
#include <functional>
#include <memory>
#include <vector>

#include "slice_geometry.h"
#include "voxray/engine/orbit.h"
#include "voxray/engine/plane_sampler.h"
#include "voxray/engine/render_params.h"
#include "voxray/io/movie_writer.h"
#include "window_level.h"

namespace voxray {

struct Volume;
class ClContext;
class Raycaster;

struct MoviePlan {
  bool cine = false;
  Orbit orbit = Orbit::Azimuth;
  Orientation view = Orientation::Axial;
  // Orbit: frames over 360 degrees. Cine: slices shown, spread evenly from the first to the
  // last; 0 = every slice.
  int frames = 0;
  // Orbit: everything but the camera's azimuth (and elevation for an elevation orbit).
  // Cine: width and height (0 x 0: the slice at its finest in-plane spacing) and interp.
  RenderParams params;
  // Cine: the slice views' window (width 0: the volume's whole value range).
  WindowLevel window{0.0, 0.0};
  // Cine over time (4D): frame K is time point K of *timePoints (one frame each; FRAMES is
  // ignored) at the view's middle slice, in one window for all. Null: a cine through slices.
  const std::vector<Volume>* timePoints = nullptr;
  // Orbit: start from params.camera (the view's) and turn from there, rather than from
  // the front as orbitCamera does (voxray-cli's movie is the orbit `bench` times).
  bool orbitFromView = false;
};

// The camera of orbit frame FRAME of FRAMES: orbitCamera's, or with orbitFromView the
// view's camera turned by 360 * FRAME / FRAMES degrees: an azimuth orbit about the long
// axis at the view's elevation, an elevation orbit over the top at the view's azimuth.
CameraParams orbitFrameCamera(const MoviePlan& plan, int frame, int frames);

// Index plane SLICE (along the voxel axis closest to the view's normal) of a cine view,
// filling SIZE pixels (0 x 0: square pixels of the plane's finer spacing) with the whole
// slice, centred. Screen axes as the slice views show them (radiological: the patient's
// right on the left; anterior or superior at the top), each the patient axis projected
// into the plane, so an oblique acquisition is shown upright.
PlaneGrid cinePlane(const Volume& v, Orientation view, int slice, glm::ivec2 size);
int cineSliceCount(const Volume& v, Orientation view);

// Settles PLAN's frame size for FORMAT: a cine's 0 x 0 becomes the slice's own size, and
// MP4 rounds an odd width or height up (movieFrameSize). Returns the size asked for before
// rounding, so that a caller can say when it changed.
MovieSize settleMovieSize(MoviePlan& plan, const Volume& v, MovieFormat format);

// How many frames PLAN makes of V (a cine's 0: every slice of the view).
int movieFrameCount(const MoviePlan& plan, const Volume& v);

// Renders one orbit frame on a device that already holds the volume (the workstation's
// RenderWorker::renderOnDevice: the 3D view's raycaster).
using MovieRenderer = std::function<Image(const RenderParams&)>;

class MovieFrames {
 public:
  // CTX renders orbits (unused for a cine; may be null then). V must outlive this.
  MovieFrames(const Volume& v, ClContext* ctx, MoviePlan plan);
  // RENDER renders orbits instead of a raycaster of its own (no second upload of V).
  MovieFrames(const Volume& v, MoviePlan plan, MovieRenderer render);
  ~MovieFrames();
  int count() const { return count_; }
  MovieSize size() const;
  // Frame K's parameters (the orbit's camera) and image.
  RenderParams params(int k) const;
  Image frame(int k);

 private:
  const Volume& v_;
  MoviePlan plan_;
  int count_ = 0;
  std::unique_ptr<Raycaster> raycaster_;
  MovieRenderer render_;
  MovieFrames(const Volume& v, ClContext* ctx, MovieRenderer render, MoviePlan plan);
};

struct MovieProgress {
  int done = 0, total = 0;
  double elapsedS = 0.0;
  double leftS = 0.0;  // estimate: the mean time per frame so far times the frames left
};

// "frame 12 of 36, about 1 min 20 s left" (no estimate before the first frame or after the
// last).
std::string describeProgress(const MovieProgress& p);

// Renders every frame into a writer for PATH (opened at the frames' size) and finishes it.
// CANCEL is polled between frames: set, it throws Error (Cancelled) and nothing is left
// under PATH. Throws Error (Output, Device) as the writer and renderer do.
void writeMovie(MovieFrames& frames, const std::string& path, const MovieSettings& settings,
                const std::function<void(const MovieProgress&)>& progress = {},
                const std::atomic<bool>* cancel = nullptr);

}  // namespace voxray
