#include "voxray/engine/reference_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "frame_setup.h"
#include "reference_sampling.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

glm::dvec3 safeNormalize(glm::dvec3 v, const glm::dvec3& fallback) {
  double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(m > 1e-6) || std::isinf(m)) return fallback;
  v /= m;
  return v / std::sqrt(glm::dot(v, v));
}

glm::dvec3 shade(const glm::dvec3& color, const glm::dvec3& normal, const glm::dvec3& pos,
                 const glm::dvec3& view, const glm::dvec3& light, const LightParams& k) {
  glm::dvec3 n = safeNormalize(normal, view);
  if (glm::dot(n, view) < 0.0) n = -n;
  glm::dvec3 l = safeNormalize(light - pos, view);
  double diffuse = std::max(glm::dot(n, l), 0.0);
  double specular = 0.0;
  if (diffuse > 0.0) {
    glm::dvec3 h = safeNormalize(l + view, n);
    specular = std::pow(std::max(glm::dot(n, h), 0.0), k.shininess);
  }
  return color * (k.ambient + k.diffuse * diffuse) + glm::dvec3(k.specular * specular);
}

struct Marcher {
  const Volume& v;
  const RenderParams& p;
  const FrameSetup& s;

  double sample(const glm::dvec3& pv) const { return sampleVolume(v, p.interp, pv); }
  bool inRange(double x) const { return x >= s.isoLoStored && x <= s.isoHiStored; }
  glm::dvec3 worldGradient(const glm::dvec3& pv) const {
    return s.view.gradToWorld * volumeGradient(v, p.interp, p.gradient, pv);
  }

  glm::dvec3 pixel(int px, int py) const {
    glm::dvec3 ow, dw;
    s.view.ray(px, py, p.width, p.height, ow, dw);
    glm::dvec3 ov = s.view.toVoxel(ow), dv = s.view.dirToVoxel(dw);
    double t0, t1;
    int axis;
    if (!intersectBox(ov, dv, s.view.clipLo, s.view.clipHi, t0, t1, axis)) return p.background;
    double step = s.stepMm, len = t1 - t0;
    int n = int(std::clamp(std::ceil(len / step), 0.0, 16777216.0));
    glm::dvec3 view = -dw;
    bool shading = p.shading && p.mode != Mode::Mip;
    if (p.mode == Mode::Iso) {
      int hit = -1;
      double tHit = 0.0;
      for (int i = 0; i <= n; ++i) {
        double t = std::min(t0 + i * step, t1);
        if (inRange(sample(ov + t * dv))) {
          hit = i;
          tHit = t;
          break;
        }
      }
      if (hit < 0) return p.background;
      if (hit > 0) {
        double a = std::min(t0 + (hit - 1) * step, t1), b = tHit;
        for (int k = 0; k < p.refine; ++k) {
          double m = 0.5 * (a + b);
          if (inRange(sample(ov + m * dv)))
            b = m;
          else
            a = m;
        }
        tHit = p.refine > 0 ? 0.5 * (a + b) : b;
      }
      glm::dvec3 pv = ov + tHit * dv;
      glm::dvec3 c(s.lut.lookup(sample(pv)));
      if (!shading) return c;
      glm::dvec3 nw;
      if (hit == 0 && axis >= 0) {
        glm::dvec3 e(0.0);
        e[axis] = 1.0;
        nw = s.view.gradToWorld * e;  // a flat cap on the clip face
      } else {
        nw = worldGradient(pv);
      }
      return shade(c, nw, ow + tHit * dw, view, s.view.lightWorld, p.light);
    }
    if (p.mode == Mode::Dvr) {
      glm::dvec3 acc(0.0);
      double alpha = 0.0;
      for (int i = 0; i < n; ++i) {
        double seg = std::min(step, len - i * step);
        double t = t0 + i * step + 0.5 * seg;
        glm::dvec3 pv = ov + t * dv;
        glm::dvec4 c = s.lut.lookup(sample(pv));
        if (c.a <= 0.0) continue;
        double a = p.opacityCorrection ? 1.0 - std::pow(1.0 - c.a, seg / s.referenceStepMm) : c.a;
        glm::dvec3 rgb(c);
        if (shading)
          rgb = shade(rgb, worldGradient(pv), ow + t * dw, view, s.view.lightWorld, p.light);
        acc += (1.0 - alpha) * a * rgb;
        alpha += (1.0 - alpha) * a;
        if (alpha >= p.earlyTermination) break;
      }
      return acc + (1.0 - alpha) * p.background;
    }
    double vmax = -std::numeric_limits<double>::infinity();
    for (int i = 0; i <= n; ++i)
      vmax = std::max(vmax, sample(ov + std::min(t0 + i * step, t1) * dv));
    return glm::dvec3(std::clamp((vmax - s.windowLoStored) * s.windowInvWidth, 0.0, 1.0));
  }
};

}  // namespace

FloatImage renderReferenceFloat(const Volume& v, const RenderParams& p) {
  FrameSetup s = makeFrameSetup(v, p);
  Marcher m{v, p, s};
  FloatImage out;
  out.width = p.width;
  out.height = p.height;
  out.rgb.resize(size_t(p.width) * size_t(p.height) * 3);
#pragma omp parallel for schedule(dynamic, 4)
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      glm::dvec3 c = glm::clamp(m.pixel(x, y), 0.0, 1.0);
      float* o = &out.rgb[(size_t(y) * size_t(p.width) + size_t(x)) * 3];
      o[0] = float(c.r);
      o[1] = float(c.g);
      o[2] = float(c.b);
    }
  return out;
}

Image quantise(const FloatImage& f) {
  Image img(f.width, f.height);
  for (size_t i = 0, n = size_t(f.width) * size_t(f.height); i < n; ++i) {
    for (int c = 0; c < 3; ++c)
      img.rgba[i * 4 + c] = uint8_t(std::lround(std::clamp(f.rgb[i * 3 + c], 0.0f, 1.0f) * 255.0f));
    img.rgba[i * 4 + 3] = 255;
  }
  return img;
}

Image renderReference(const Volume& v, const RenderParams& p) {
  return quantise(renderReferenceFloat(v, p));
}

}  // namespace voxray
