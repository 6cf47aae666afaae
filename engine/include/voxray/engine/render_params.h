#pragma once
// Everything that decides what a frame looks like, declared once. voxray-cli builds
// its flags from renderParamSpecs(), the workstation binds its models to the same
// fields, and saved state is the same key=value text.
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/param_spec.h"
#include "voxray/engine/tf2d.h"
#include "voxray/engine/transfer_function.h"

namespace voxray {

enum class Mode { Iso, Dvr, Mip };
enum class Gradient { Central, Sobel, ZuckerHummel };
enum class Interp { Nearest, Linear };
enum class Projection { Perspective, Orthographic };
// How samples are lit (issue 15): local Blinn-Phong, Phong attenuated by the volume between
// sample and light, Phong with ambient occlusion, or the progressive path tracer.
enum class Lighting { Phong, Shadows, Ao, Cinematic };

struct CameraParams {
  double azimuthDeg = 0.0;    // 0 = anterior view; 90 = from the patient's left
  double elevationDeg = 0.0;  // 90 = from above (superior)
  double zoom = 1.0;
  double distanceMm = 0.0;  // eye to volume centre; 0 = frame the whole volume
  glm::dvec2 panMm{0.0};    // moves the look-at point in the view plane
  Projection projection = Projection::Perspective;
  double fovDeg = 30.0;
};

// The seed's "bounding box" cut, in fractions of the volume's extent along i, j, k.
struct ClipBox {
  glm::dvec3 lo{0.0};
  glm::dvec3 hi{1.0};
  bool isFull() const { return lo == glm::dvec3(0.0) && hi == glm::dvec3(1.0); }
};

struct LightParams {
  // With followCamera: in the camera's frame (x right, y up, z towards the viewer,
  // origin at the eye) in units of the volume's radius; otherwise in mm, patient LPS
  // relative to the volume centre.
  glm::dvec3 position{0.5, 0.6, 0.0};
  bool followCamera = true;
  double ambient = 0.15;
  double diffuse = 0.75;
  double specular = 0.25;
  double shininess = 32.0;
};

// dvr with a segmentation (issue 34, Raycaster::setSegmentation): which labels the volume
// shows. Off: all of it; Show: only samples whose nearest voxel holds one of `labels` (what
// a segment covers, e.g. bone without the table); Hide: all but those.
struct SegmentMask {
  enum class Kind { Off, Show, Hide } kind = Kind::Off;
  std::vector<int> labels;  // 1 ... 255, sorted, each once
  bool operator==(const SegmentMask& o) const { return kind == o.kind && labels == o.labels; }
  bool operator!=(const SegmentMask& o) const { return !(*this == o); }
};

struct RenderParams {
  int width = 512;
  int height = 384;
  Mode mode = Mode::Iso;
  std::string preset;          // transfer-function preset name; empty = mode's default
  double presetShiftHu = 0.0;  // moves every control point of the preset along HU
  // A custom table (sorted by HU; a repeated HU makes a step) used instead of the
  // preset's; the shift moves it too. Empty: the preset's.
  std::vector<ControlPoint> transferFunction;
  // The ray length (mm) over which the table's opacities hold; 0 = the smallest voxel
  // spacing, what the presets are made for (issue 35: Slicer's scalar opacity unit distance).
  double opacityUnitMm = 0.0;
  // dvr: each sample's opacity times a factor of the gradient magnitude there (issue 35; VTK's
  // and Slicer's gradient opacity): points (|gradient| in HU/mm, factor 0 ... 1) sorted by
  // |gradient|, linear between, constant beyond the ends. Empty: off (factor 1).
  std::vector<glm::dvec2> gradientOpacity;
  // dvr: the 2D transfer function over (HU, |gradient|) (issue 35, voxray/engine/tf2d.h). When
  // set it replaces the table's colour and opacity and the gradient opacity. Empty: off.
  Tf2d tf2d;
  double isoLo = 400.0;  // HU range of the first-hit surface (the seed's two sliders)
  double isoHi = 32767.0;
  Gradient gradient = Gradient::Central;
  Interp interp = Interp::Linear;
  double stepMm = 0.0;  // 0 = half the smallest voxel spacing (step.h)
  int refine = 4;       // bisection steps refining an iso hit
  bool shading = true;
  bool opacityCorrection = true;
  bool jitter = false;  // offset each ray's first sample by a per-pixel fraction of a step
  double earlyTermination = 0.99;  // dvr: stop once this opacity is reached
  // dvr: 2 or 4 times longer steps in macro cells where the table varies little enough that
  // each long step changes the composite by at most this (kernels/empty_space/classify.cl,
  // adaptive_level); 0 = every step the base step. Needs opacity correction.
  double adaptiveError = 0.0;
  // dvr: pre-integrated classification (issue 40, voxray/engine/preint_table.h): each segment
  // classified over the values between its two samples, so long steps keep thin features. The
  // raycaster's only (the reference renderer stays the plain integral it is measured against);
  // not with tf2d, gradientOpacity, a segmentation or an overlay (then off), nor adaptiveError.
  bool preintegrate = false;
  // Image-space adaptive sampling (issue 40, the raycaster's; engine/src/adaptive_image.h):
  // rays at every adaptiveImageSpacing-th pixel first, then every pixel of the blocks between
  // them whose corners differ by adaptiveImage levels (of 255) or more in a channel, the rest
  // bilinear. Below 0: off (every pixel marched); 0: every block refined (the plain frame).
  double adaptiveImage = -1.0;
  int adaptiveImageSpacing = 4;  // 2 ... 8 pixels
  // dvr with a segmentation: the labels shown (segment-mask) and how strongly a visible
  // segment's colour replaces the table's colour (0: not at all, 1: wholly).
  SegmentMask segmentMask;
  double segmentBlend = 1.0;
  // dvr with a segmentation: segments with their own transfer function (issue 35), by label
  // 1 ... 255: a table in HU as transferFunction, used instead of the volume's (and of the
  // segment's colour) for the samples whose nearest voxel holds that label, where a visible
  // segment names it. Not with tf2d (the 2D table stays the volume's). Empty: none.
  std::map<int, std::vector<ControlPoint>> segmentTfs;
  double windowWidth = 0.0;  // mip grey mapping in HU; width 0 = the volume's range
  double windowLevel = 0.0;
  glm::dvec3 surfaceColor{0.93, 0.89, 0.80};  // iso colour (bone) when no preset colours it
  glm::dvec3 background{0.0};
  CameraParams camera;
  ClipBox clip;
  LightParams light;
  Lighting lighting = Lighting::Phong;
};

// One declared render parameter: its key (the CLI flag without "--"), help, domain (enum
// labels, number range) and how to read and write it as text.
using ParamSpec = Spec<RenderParams>;
const std::vector<ParamSpec>& renderParamSpecs();
// The spec of KEY; throws Error (Input) for an unknown key.
const ParamSpec& findRenderParamSpec(const std::string& key);

// VALUES by key (voxray-cli's flags, the workstation's command line): a preset first, then
// every value given in declaration order, so that explicit values win over what the preset
// brings (mode, iso range, window). Throws Error (Input) for an unknown preset or bad value.
void applyRenderValues(RenderParams& p, const std::map<std::string, std::string>& values);

// key=value lines, one per declared parameter (saved state, logs, test names).
std::string toText(const RenderParams& p);
void fromText(RenderParams& p, const std::string& text);  // throws Error (Input)

// The names from the specs' label tables ("iso", "zucker-hummel"); parse* accept aliases too.
const char* toString(Mode m);
const char* toString(Gradient g);
const char* toString(Interp i);
const char* toString(Lighting l);
Mode parseMode(const std::string& s);
Gradient parseGradient(const std::string& s);
Interp parseInterp(const std::string& s);
Lighting parseLighting(const std::string& s);
// "off", "show:1,2", "hide:3" (segment-mask); throws Error (Input) naming what is wrong.
SegmentMask parseSegmentMask(const std::string& s);
std::string toString(const SegmentMask& m);

}  // namespace voxray
