#include <algorithm>
#include <cmath>

#include "voxray/io/error.h"
#include "voxray/io/statistics.h"
#include "voxray/lab/accuracy.h"

namespace voxray {

namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

std::vector<double> luma(const FloatImage& f) {
  std::vector<double> y(size_t(f.width) * size_t(f.height));
  for (size_t i = 0; i < y.size(); ++i)
    y[i] = 0.299 * f.rgb[i * 3] + 0.587 * f.rgb[i * 3 + 1] + 0.114 * f.rgb[i * 3 + 2];
  return y;
}

// Separable Gaussian blur, weights renormalised at the borders so small images work.
std::vector<double> blur(const std::vector<double>& in, int w, int h) {
  const int r = 5;
  double k[2 * r + 1];
  for (int i = -r; i <= r; ++i) k[i + r] = std::exp(-0.5 * i * i / (1.5 * 1.5));
  std::vector<double> tmp(in.size()), out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0.0, ws = 0.0;
      for (int i = std::max(-r, -x); i <= std::min(r, w - 1 - x); ++i) {
        s += k[i + r] * in[size_t(y) * w + x + i];
        ws += k[i + r];
      }
      tmp[size_t(y) * w + x] = s / ws;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0.0, ws = 0.0;
      for (int i = std::max(-r, -y); i <= std::min(r, h - 1 - y); ++i) {
        s += k[i + r] * tmp[size_t(y + i) * w + x];
        ws += k[i + r];
      }
      out[size_t(y) * w + x] = s / ws;
    }
  return out;
}

double ssim(const FloatImage& a, const FloatImage& b) {
  const int w = a.width, h = a.height;
  std::vector<double> x = luma(a), y = luma(b), xx(x.size()), yy(x.size()), xy(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  auto mx = blur(x, w, h), my = blur(y, w, h), sxx = blur(xx, w, h), syy = blur(yy, w, h),
       sxy = blur(xy, w, h);
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;  // (K L)^2 with peak L = 1
  double sum = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    double vx = sxx[i] - mx[i] * mx[i], vy = syy[i] - my[i] * my[i];
    double cov = sxy[i] - mx[i] * my[i];
    sum += (2.0 * mx[i] * my[i] + c1) * (2.0 * cov + c2) /
           ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
  }
  return x.empty() ? 1.0 : sum / double(x.size());
}

}  // namespace

FloatImage toFloatImage(const Image& image) {
  FloatImage f;
  f.width = image.width;
  f.height = image.height;
  size_t n = size_t(image.width) * size_t(image.height);
  f.rgb.resize(n * 3);
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) f.rgb[i * 3 + c] = float(image.rgba[i * 4 + c]) / 255.0f;
  return f;
}

ImageError compareImages(const FloatImage& test, const FloatImage& reference) {
  if (test.width != reference.width || test.height != reference.height)
    throw Error(Error::Kind::Internal, "compareImages: the images differ in size");
  ImageError e;
  double se = 0.0, ae = 0.0;
  for (size_t i = 0; i < test.rgb.size(); ++i) {
    double d = double(test.rgb[i]) - double(reference.rgb[i]);
    se += d * d;
    ae += std::abs(d);
  }
  double n = std::max<double>(1.0, double(test.rgb.size()));
  e.rmse = std::sqrt(se / n);
  e.meanAbs = ae / n;
  e.psnrDb = e.rmse > 0.0 ? std::min(99.0, -20.0 * std::log10(e.rmse)) : 99.0;
  e.ssim = ssim(test, reference);
  return e;
}

ErrorStats summarize(std::vector<double> values) {
  ErrorStats s;
  s.count = int(values.size());
  if (values.empty()) return s;
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / double(values.size());
  s.median = quantile(values, 0.5);  // the upper middle value: one of the errors
  s.p95 = quantile(values, 0.95);
  s.max = *std::max_element(values.begin(), values.end());
  return s;
}

SurfaceError surfaceError(const ReferenceHits& hits, const AnalyticField& truth) {
  std::vector<double> pos, ang;
  for (size_t i = 0; i < hits.kind.size(); ++i) {
    if (hits.kind[i] != HitKind::Surface) continue;
    pos.push_back(truth.surfaceDistance(hits.voxel[i]));
    glm::dvec3 g = hits.gradToWorld * truth.gradient(hits.voxel[i]);
    double gl = glm::length(g), nl = glm::length(hits.normal[i]);
    if (!(gl > 0.0) || !(nl > 0.0)) continue;  // no defined normal: nothing to compare
    double c = std::clamp(glm::dot(g / gl, hits.normal[i] / nl), -1.0, 1.0);
    ang.push_back(std::acos(c) * kRadToDeg);
  }
  return {summarize(std::move(pos)), summarize(std::move(ang))};
}

ReferenceHits kernelHits(const std::vector<glm::vec4>& hits, int width, int height) {
  ReferenceHits out;
  out.width = width;
  out.height = height;
  out.kind.reserve(hits.size());
  out.voxel.reserve(hits.size());
  for (const glm::vec4& h : hits) {
    out.kind.push_back(h.w > 0.5f ? HitKind::Surface
                                  : (h.w > -0.5f ? HitKind::AtEntry : HitKind::None));
    out.voxel.push_back(glm::dvec3(h));
  }
  out.normal.assign(hits.size(), glm::dvec3(0.0));
  return out;
}

ErrorStats hitPointError(const ReferenceHits& hits, const ReferenceHits& fine,
                         double sameCrossingVoxels) {
  std::vector<double> d;
  int excluded = 0;
  size_t n = std::min(hits.kind.size(), fine.kind.size());
  for (size_t i = 0; i < n; ++i) {
    if (hits.kind[i] != HitKind::Surface || fine.kind[i] != HitKind::Surface) continue;
    double e = glm::length(hits.voxel[i] - fine.voxel[i]);
    if (e > sameCrossingVoxels)
      ++excluded;
    else
      d.push_back(e);
  }
  ErrorStats s = summarize(std::move(d));
  s.excluded = excluded;
  return s;
}

}  // namespace voxray
