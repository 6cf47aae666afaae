#pragma once
// The same maths as the kernels, in double precision on the host, without OpenCL.
// Tests compare the kernels against it pixel by pixel; it is also the ground truth
// for the accuracy sweep, which reads the per-pixel hit points it can return.
#include <cstdint>
#include <vector>

#include "voxray/engine/render_params.h"
#include "voxray/io/image.h"

namespace voxray {

struct Volume;
struct Segmentation;

// Linear RGB in 0..1 per pixel, before quantisation to 8 bits.
struct FloatImage {
  int width = 0, height = 0;
  std::vector<float> rgb;
};

// What an iso ray found, per pixel (row-major like the image).
enum class HitKind : uint8_t {
  None,     // background: missed the box or never reached the iso range
  Surface,  // a crossing found by marching (and bisection): the surface position
  AtEntry   // the first sample was already in range: a clip cap or the box face
};

struct ReferenceHits {
  int width = 0, height = 0;
  std::vector<HitKind> kind;
  std::vector<glm::dvec3> voxel;   // hit point, voxel coordinates
  std::vector<glm::dvec3> normal;  // unit gradient direction in world (not flipped to the eye)
  glm::dmat3 gradToWorld{1.0};     // how a voxel-axis gradient becomes a world one
  double samples = 0.0;            // volume reads of the frame (all modes), for samples/s
};

FloatImage renderReferenceFloat(const Volume& v, const RenderParams& p);
// The same, also filling hits (iso hit points and normals; samples for every mode).
FloatImage renderReferenceFloat(const Volume& v, const RenderParams& p, ReferenceHits* hits);
Image renderReference(const Volume& v, const RenderParams& p);
// Label-aware dvr (issue 34), as Raycaster::setSegmentation: SEG lies on V's grid.
FloatImage renderReferenceFloat(const Volume& v, const RenderParams& p, const Segmentation& seg);
Image renderReference(const Volume& v, const RenderParams& p, const Segmentation& seg);
// Fused dvr (issue 36), as Raycaster::setOverlay: OVERLAY with its table TF on its own grid.
FloatImage renderReferenceFloat(const Volume& v, const RenderParams& p, const Volume& overlay,
                                const TransferFunction& tf);
Image renderReference(const Volume& v, const RenderParams& p, const Volume& overlay,
                      const TransferFunction& tf);
Image quantise(const FloatImage& f);

}  // namespace voxray
