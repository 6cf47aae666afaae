#include "voxray/engine/reference_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "frame_setup.h"
#include "kernel_switches.h"
#include "label_table.h"
#include "reference_hooks.h"
#include "reference_sampling.h"
#include "voxray/engine/overlay.h"
#include "voxray/io/error.h"
#include "voxray/io/parallel.h"
#include "voxray/io/segmentation.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

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

// What one ray leaves besides its colour.
struct PixelOut {
  HitKind kind = HitKind::None;
  glm::dvec3 voxel{0.0}, normal{0.0};
  double samples = 0.0;
};

struct Marcher {
  const Volume& v;
  const RenderParams& p;
  const FrameSetup& s;
  bool shading = kernelSwitches(p).SHADING != 0;  // the kernels' rules
  bool gradientOpacity = kernelSwitches(p).GRADIENT_OPACITY != 0;
  bool tf2d = kernelSwitches(p).TF2D != 0;
  double gradSamples = double(gradientSamples(p.gradient));
  const ReferenceHooks* hooks = nullptr;
  // Label-aware dvr (kernels/classification/labels.cl): the label map and segment table, or
  // none (no segmentation, not dvr, or a table that changes nothing, as the raycaster).
  const Segmentation* labelMap = nullptr;
  std::vector<glm::vec4> segTable{};
  // Fused dvr (kernels/classification/overlay.cl), or none.
  const OverlayClassifier* overlay = nullptr;

  // C classified by the label of the voxel nearest to pv (label_classify).
  glm::dvec4 labelled(const glm::dvec4& c, const glm::dvec3& pv) const {
    glm::ivec3 i = glm::clamp(glm::ivec3(glm::floor(pv + 0.5)), glm::ivec3(0), v.dims - 1);
    size_t l = labelMap->labels[labelMap->grid.index(i.x, i.y, i.z)];
    glm::dvec4 s(segTable[2 * l]);
    return glm::dvec4(glm::mix(glm::dvec3(c), glm::dvec3(s), s.w),
                      c.a * double(segTable[2 * l + 1].x));
  }

  // The light coefficients at world position w: the frame's, or the Monte Carlo estimator's.
  LightParams lightAt(const glm::dvec3& w, Rng& rng) const {
    return hooks ? hooks->light(w, rng) : p.light;
  }

  double sample(const glm::dvec3& pv, PixelOut& o) const {
    o.samples += 1.0;
    return sampleVolume(v, p.interp, pv);
  }
  glm::dvec3 worldGradient(const glm::dvec3& pv, PixelOut& o) const {
    o.samples += gradSamples;
    return s.view.gradToWorld * volumeGradient(v, p.interp, p.gradient, pv);
  }

  // The jitter placement of kernels/raycast.cl: samples shift forward by j steps.
  glm::dvec3 pixel(int px, int py, PixelOut& o) const {
    PixelRay r;
    if (!pixelRay(s.view, px, py, p.width, p.height, r)) return p.background;
    const glm::dvec3 &ow = r.ow, &dw = r.dw, &ov = r.ov, &dv = r.dv;
    double t0 = r.t0, t1 = r.t1;
    int axis = r.axis;
    double step = s.stepMm, len = t1 - t0;
    int n = int(std::clamp(std::ceil(len / step), 0.0, 16777216.0));
    Rng rng;
    double j = p.jitter ? double(jitterFraction(px, py)) : 0.0;
    if (hooks) {  // a realisation: its own jitter, uniform in [0, 1)
      rng.seed(hooks->stream * 0x9E3779B97F4A7C15ull ^ (uint64_t(py) << 32 | uint64_t(px)));
      j = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    }
    auto at = [&](int i) { return std::min(t0 + (i + j) * step, t1); };
    glm::dvec3 view = -dw;
    if (p.mode == Mode::Iso) return iso(ov, dv, ow, dw, at, n, axis, o, rng);
    if (p.mode == Mode::Dvr) {
      glm::dvec3 acc(0.0);
      double alpha = 0.0;
      for (int i = 0; i <= n; ++i) {
        // Segment i ends at the i-th (jittered) sample position; segment 0 is the stub
        // of j steps before it, empty without jitter.
        double a = std::max(t0, t0 + (i - 1 + j) * step), b = at(i);
        if (!(b > a)) continue;
        double seg = b - a, t = a + 0.5 * seg;
        glm::dvec3 pv = ov + t * dv;
        const double value = sample(pv, o);
        glm::dvec4 c = s.lut.lookup(value);
        // The overlay's sample at the same point (march.cl's dvr_segment, OVERLAY).
        const glm::dvec4 ov = overlay ? overlay->at(pv) : glm::dvec4(0.0);
        auto nothing = [&] { return c.a <= 0.0 && ov.a <= 0.0; };
        if (nothing()) continue;
        glm::dvec3 g(0.0);
        if (tf2d) {  // the 2D table at (value, |gradient|) where the 1D (its largest) shows
          if (c.a > 0.0) {
            g = worldGradient(pv, o);
            c = s.tf2d.lookup(value, glm::length(g));
          }
          if (nothing()) continue;
        }
        if (labelMap) {
          c = labelled(c, pv);
          if (nothing()) continue;
        }
        if (gradientOpacity) {  // the factor at |gradient| (stored units per mm), then shading
          if (c.a > 0.0) {
            g = worldGradient(pv, o);
            c.a *= s.gradient.lookup(glm::length(g));
          }
          if (nothing()) continue;
        }
        glm::dvec3 rgb(c);
        if (shading && c.a > 0.0)
          rgb = shade(rgb, gradientOpacity || tf2d ? g : worldGradient(pv, o), ow + t * dw, view,
                      s.view.lightWorld, lightAt(ow + t * dw, rng));
        if (overlay) {  // summed extinction, colours weighted by opacity (march.cl says why)
          rgb = (c.a * rgb + ov.a * glm::dvec3(ov)) / (c.a + ov.a);
          c.a = 1.0 - (1.0 - c.a) * (1.0 - ov.a);
        }
        double al = p.opacityCorrection ? 1.0 - std::pow(1.0 - c.a, seg / s.referenceStepMm) : c.a;
        acc += (1.0 - alpha) * al * rgb;
        alpha += (1.0 - alpha) * al;
        if (alpha >= p.earlyTermination) break;
      }
      return acc + (1.0 - alpha) * p.background;
    }
    double vmax = -std::numeric_limits<double>::infinity();
    for (int i = 0; i <= n; ++i) vmax = std::max(vmax, sample(ov + at(i) * dv, o));
    const glm::dvec3 grey(std::clamp((vmax - s.windowLoStored) * s.windowInvWidth, 0.0, 1.0));
    if (!overlay) return grey;
    // Fused mip (overlay.cl's overlay_mip): the overlay's largest value at the same samples.
    double omax = -std::numeric_limits<double>::infinity(), value = 0.0;
    for (int i = 0; i <= n; ++i)
      if (overlay->value(ov + at(i) * dv, value)) omax = std::max(omax, value);
    return std::isinf(omax) ? grey : overlay->overMip(grey, omax);
  }

  template <class At>
  glm::dvec3 iso(const glm::dvec3& ov, const glm::dvec3& dv, const glm::dvec3& ow,
                 const glm::dvec3& dw, At at, int n, int axis, PixelOut& o, Rng& rng) const {
    int hit = -1;
    double tHit = 0.0;
    for (int i = 0; i <= n; ++i) {
      double t = at(i);
      if (s.inIso(sample(ov + t * dv, o))) {
        hit = i;
        tHit = t;
        break;
      }
    }
    if (hit < 0) return p.background;
    if (hit > 0) {
      double a = at(hit - 1), b = tHit;
      for (int k = 0; k < p.refine; ++k) {
        double m = 0.5 * (a + b);
        if (s.inIso(sample(ov + m * dv, o)))
          b = m;
        else
          a = m;
      }
      tHit = p.refine > 0 ? 0.5 * (a + b) : b;
    }
    glm::dvec3 pv = ov + tHit * dv;
    glm::dvec3 c(s.lut.lookup(sample(pv, o)));
    o.kind = hit > 0 ? HitKind::Surface : HitKind::AtEntry;
    o.voxel = pv;
    bool cap = hit == 0 && axis >= 0;
    glm::dvec3 nw;
    if (cap) {
      glm::dvec3 e(0.0);
      e[axis] = 1.0;
      nw = s.view.gradToWorld * e;  // a flat cap on the clip face
    } else if (shading) {
      nw = worldGradient(pv, o);
    } else if (o.kind == HitKind::Surface) {
      // Only for the hits output: the kernel takes no gradient here, so it is not counted.
      nw = s.view.gradToWorld * volumeGradient(v, p.interp, p.gradient, pv);
    }
    o.normal = safeNormalize(nw, glm::dvec3(0.0));
    if (!shading) return c;
    return shade(c, nw, ow + tHit * dw, -dw, s.view.lightWorld, lightAt(ow + tHit * dw, rng));
  }
};

}  // namespace

FloatImage renderReferenceFloat(const Volume& v, const RenderParams& p) {
  return renderReferenceFloat(v, p, nullptr);
}

FloatImage renderReferenceFloat(const Volume& v, const RenderParams& p, ReferenceHits* hits) {
  return renderReferenceFloat(v, p, hits, nullptr);
}

FloatImage renderReferenceFloat(const Volume& v, const RenderParams& p, const Segmentation& seg) {
  return renderReferenceFloat(v, p, nullptr, nullptr, &seg);
}

Image renderReference(const Volume& v, const RenderParams& p, const Segmentation& seg) {
  return quantise(renderReferenceFloat(v, p, seg));
}

FloatImage renderReferenceFloat(const Volume& v, const RenderParams& p, const Volume& overlay,
                                const TransferFunction& tf) {
  const OverlayClassifier c(v, overlay, tf);
  return renderReferenceFloat(v, p, nullptr, nullptr, nullptr, &c);
}

Image renderReference(const Volume& v, const RenderParams& p, const Volume& overlay,
                      const TransferFunction& tf) {
  return quantise(renderReferenceFloat(v, p, overlay, tf));
}

FloatImage renderReferenceFloat(const Volume& v, const RenderParams& p, ReferenceHits* hits,
                                const ReferenceHooks* hooks, const Segmentation* seg,
                                const OverlayClassifier* overlay) {
  FrameSetup s = makeFrameSetup(v, p);
  Marcher m{v, p, s};
  m.hooks = hooks;
  if (p.mode == Mode::Dvr || p.mode == Mode::Mip) m.overlay = overlay;
  if (seg && p.mode == Mode::Dvr) {
    if (seg->grid.dims != v.dims || seg->labels.size() != v.voxelCount())
      throw inputError("the segmentation's label map does not lie on the volume's voxels");
    m.segTable = segmentTable(seg->segments, p);
    if (!changesNothing(m.segTable)) m.labelMap = seg;
  }
  FloatImage out;
  out.width = p.width;
  out.height = p.height;
  size_t pixels = size_t(p.width) * size_t(p.height);
  out.rgb.resize(pixels * 3);
  if (hits) {
    hits->width = p.width;
    hits->height = p.height;
    hits->kind.assign(pixels, HitKind::None);
    hits->voxel.assign(pixels, glm::dvec3(0.0));
    hits->normal.assign(pixels, glm::dvec3(0.0));
    hits->gradToWorld = s.view.gradToWorld;
  }
  // One row per index. Samples are summed per row, then the rows in order, so the total
  // does not depend on the scheduling.
  std::vector<double> rowSamples(size_t(p.height), 0.0);
  parallelFor(size_t(p.height), [&](size_t row) {
    const int y = int(row);
    for (int x = 0; x < p.width; ++x) {
      PixelOut po;
      // No clamp here: a NaN must reach the caller (tests look for it), not turn into 0.
      glm::dvec3 c = m.pixel(x, y, po);
      for (int k = 0; k < 3; ++k) c[k] = c[k] < 0.0 ? 0.0 : (c[k] > 1.0 ? 1.0 : c[k]);
      size_t i = size_t(y) * size_t(p.width) + size_t(x);
      float* o = &out.rgb[i * 3];
      o[0] = float(c.r);
      o[1] = float(c.g);
      o[2] = float(c.b);
      rowSamples[row] += po.samples;
      if (hits) {
        hits->kind[i] = po.kind;
        hits->voxel[i] = po.voxel;
        hits->normal[i] = po.normal;
      }
    }
  });
  double samples = 0.0;
  for (double r : rowSamples) samples += r;
  if (hits) hits->samples = samples;
  return out;
}

Image quantise(const FloatImage& f) {
  Image img(f.width, f.height);
  for (size_t i = 0, n = size_t(f.width) * size_t(f.height); i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      float x = f.rgb[i * 3 + c];
      x = x > 0.0f ? std::min(x, 1.0f) : 0.0f;  // NaN becomes 0, as convert_uchar_sat does
      img.rgba[i * 4 + c] = uint8_t(std::lround(x * 255.0f));
    }
    img.rgba[i * 4 + 3] = 255;
  }
  return img;
}

Image renderReference(const Volume& v, const RenderParams& p) {
  return quantise(renderReferenceFloat(v, p));
}

}  // namespace voxray
