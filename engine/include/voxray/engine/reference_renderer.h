#pragma once
// The same maths as the kernels, in double precision on the host, without OpenCL.
// Tests compare the kernels against it pixel by pixel; it is also the ground truth
// for the accuracy sweep.
#include "voxray/engine/render_params.h"
#include "voxray/io/image.h"

namespace voxray {

struct Volume;

// Linear RGB in 0..1 per pixel, before quantisation to 8 bits.
struct FloatImage {
  int width = 0, height = 0;
  std::vector<float> rgb;
};

FloatImage renderReferenceFloat(const Volume& v, const RenderParams& p);
Image renderReference(const Volume& v, const RenderParams& p);
Image quantise(const FloatImage& f);

}  // namespace voxray
