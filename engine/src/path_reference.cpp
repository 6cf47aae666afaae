#include "voxray/engine/path_reference.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "frame_setup.h"
#include "path_rng.h"
#include "reference_sampling.h"
#include "voxray/io/error.h"
#include "voxray/io/parallel.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

constexpr int kMaxSteps = 1048576;  // as PT_MAX_STEPS in kernels/lighting/path_trace.cl

struct Rng {
  voxray_u32 key;
  voxray_u32 i = 0;
  double uniform() { return double(voxray_path_bits(key, i++)) * VOXRAY_PATH_UNIT; }
  double freePath(double majorant) { return -std::log(1.0 - uniform()) / majorant; }
};

struct Tracer {
  const Volume& v;
  const RenderParams& p;
  const FrameSetup& s;
  const PathTracerOptions& o;
  double majorant;

  double sigma(const glm::dvec3& pv, glm::dvec3& albedo) const {
    glm::dvec4 c = s.lut.lookup(sampleVolume(v, p.interp, pv));
    albedo = glm::dvec3(c);
    return -std::log1p(-std::clamp(c.a, 0.0, o.opacityCap)) / s.referenceStepMm;
  }
  double exit(const glm::dvec3& pv, const glm::dvec3& dv) const {
    double t0, t1;
    int axis;
    if (!intersectBox(pv, dv, s.view.clipLo, s.view.clipHi, t0, t1, axis)) return 0.0;
    return std::max(t1, 0.0);
  }
  double transmittance(const glm::dvec3& pv, const glm::dvec3& dv, double tMax, Rng& r) const {
    if (!(majorant > 0.0)) return 1.0;
    double tr = 1.0, t = 0.0;
    glm::dvec3 albedo;
    for (int k = 0; k < kMaxSteps && tr > 0.0; ++k) {
      t += r.freePath(majorant);
      if (!(t < tMax)) break;
      tr *= std::max(0.0, 1.0 - sigma(pv + t * dv, albedo) / majorant);
      if (tr < 0.1) tr = r.uniform() < 0.5 ? 0.0 : 2.0 * tr;  // the kernel's draws, in order
    }
    return tr;
  }
  glm::dvec3 direction(Rng& r) const {
    double z = 1.0 - 2.0 * r.uniform();
    double phi = 6.28318530717958647692 * r.uniform();
    double sn = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {sn * std::cos(phi), sn * std::sin(phi), z};
  }

  glm::dvec3 path(int px, int py, Rng& r) const {
    PixelRay pr;
    if (!pixelRay(s.view, px, py, p.width, p.height, pr)) return p.background;
    glm::dvec3 ow = pr.ow, dw = pr.dw, ov = pr.ov, dv = pr.dv;
    double t0 = pr.t0, t1 = pr.t1;
    glm::dvec3 beta(1.0), radiance(0.0);
    for (int bounce = 0;; ++bounce) {
      double t = t0;
      bool collided = false;
      glm::dvec3 albedo(0.0);
      if (majorant > 0.0) {
        for (int k = 0; k < kMaxSteps; ++k) {
          t += r.freePath(majorant);
          if (!(t < t1)) break;
          double sg = sigma(ov + t * dv, albedo);
          if (r.uniform() * majorant < sg) {
            collided = true;
            break;
          }
        }
      }
      if (!collided) {
        radiance += beta * (bounce == 0 ? p.background : glm::dvec3(p.light.ambient));
        break;
      }
      if (bounce == o.maxBounces) break;
      glm::dvec3 xw = ow + t * dw, xv = ov + t * dv;
      beta *= albedo;
      if (!(std::max({beta.x, beta.y, beta.z}) > 0.0)) break;
      glm::dvec3 toLight = s.view.lightWorld - xw;
      glm::dvec3 lw = safeNormalize(toLight, -dw), lv = s.view.dirToVoxel(lw);
      double reach = std::min(exit(xv, lv), std::max(glm::dot(toLight, lw), 0.0));
      radiance += beta * p.light.diffuse * transmittance(xv, lv, reach, r);
      dw = direction(r);
      dv = s.view.dirToVoxel(dw);
      ow = xw;
      ov = xv;
      t0 = 0.0;
      t1 = exit(xv, dv);
    }
    return radiance;
  }
};

}  // namespace

PathReference renderPathReference(const Volume& v, const RenderParams& params, int samples,
                                  const PathTracerOptions& o) {
  if (samples < 2) throw inputError("the path reference needs at least 2 samples per pixel");
  if (o.maxBounces < 1 || o.maxBounces > 64 || !(o.opacityCap > 0.0 && o.opacityCap < 1.0))
    throw inputError("path tracer options out of range (bounces 1 ... 64, cap in (0, 1))");
  RenderParams p = cinematicFrame(params);
  FrameSetup s = makeFrameSetup(v, p);
  Tracer tr{v, p, s, o, pathMajorant(s.lut, s.referenceStepMm, o.opacityCap)};
  PathReference ref;
  ref.samples = samples;
  for (FloatImage* f : {&ref.mean, &ref.standardError}) {
    f->width = p.width;
    f->height = p.height;
    f->rgb.assign(size_t(p.width) * size_t(p.height) * 3, 0.0f);
  }
  parallelFor(size_t(p.height), [&](size_t row) {
    const int y = int(row);
    for (int x = 0; x < p.width; ++x) {
      voxray_u32 pixel = voxray_u32(y) * voxray_u32(p.width) + voxray_u32(x);
      glm::dvec3 sum(0.0), sq(0.0);
      for (int k = 0; k < samples; ++k) {
        Rng r{voxray_path_key(o.seed, pixel, voxray_u32(k))};
        glm::dvec3 l = tr.path(x, y, r);
        sum += l;
        sq += l * l;
      }
      glm::dvec3 mean = sum / double(samples);
      glm::dvec3 var = (sq - double(samples) * mean * mean) / double(samples - 1);
      for (int c = 0; c < 3; ++c) {
        ref.mean.rgb[size_t(pixel) * 3 + c] = float(mean[c]);
        ref.standardError.rgb[size_t(pixel) * 3 + c] =
            float(std::sqrt(std::max(var[c], 0.0) / double(samples)));
      }
    }
  });
  return ref;
}

}  // namespace voxray
