#include "lighting_scenes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "voxray/engine/camera.h"
#include "voxray/io/image.h"

namespace voxray::test {

Volume sdfVolume(glm::ivec3 dims, const std::function<double(const glm::dvec3&)>& sdf) {
  Volume v;
  v.dims = dims;
  v.voxels.resize(v.voxelCount());
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) {
        double d = sdf(glm::dvec3(x, y, z));
        v.voxels[v.index(x, y, z)] = int16_t(std::lround(std::clamp(-1000.0 * d, -1000.0, 1000.0)));
      }
  return v;
}

std::vector<ControlPoint> opaqueAboveZero() {
  return {
      {-1000.0, {1, 1, 1, 0}}, {0.0, {1, 1, 1, 0}}, {0.0, {1, 1, 1, 1}}, {1000.0, {1, 1, 1, 1}}};
}

std::vector<ControlPoint> uniformOpacity(double alpha) {
  return {{-32768.0, {1, 1, 1, alpha}}, {32767.0, {1, 1, 1, alpha}}};
}

glm::dvec3 worldOf(const Volume& v, const glm::dvec3& pv) {
  ViewGeometry g = makeViewGeometry(v, RenderParams{});
  return glm::inverse(g.worldToVoxel) * (pv - g.voxelCentre);
}

RenderParams litParams(Lighting lighting, const std::vector<ControlPoint>& tf,
                       glm::dvec3 lightWorld, int width, int height) {
  RenderParams p;
  p.width = width;
  p.height = height;
  p.mode = Mode::Dvr;
  p.transferFunction = tf;
  p.camera.projection = Projection::Orthographic;
  p.light.followCamera = false;
  p.light.position = lightWorld;
  p.lighting = lighting;
  return p;
}

SlabScene slabScene() {
  SlabScene s;
  s.volume = sdfVolume({32, 32, 48}, [](const glm::dvec3& q) {
    return std::abs(q.z - 33.0) - 3.0 < 0.0 ? -1.0 : 0.5 + 0.01 * q.z;
  });
  std::vector<ControlPoint> tf = {{-1000.0, {1, 1, 1, 0.05}},
                                  {-1.0, {1, 1, 1, 0.05}},
                                  {0.0, {1, 1, 1, 1}},
                                  {1000.0, {1, 1, 1, 1}}};
  s.above = litParams(Lighting::Shadows, tf, glm::dvec3(0.0, 0.0, 300.0));
  s.ambientOnly = s.above;
  s.ambientOnly.lighting = Lighting::Phong;
  s.ambientOnly.light.diffuse = s.ambientOnly.light.specular = 0.0;
  s.below = s.above;
  s.below.light.position = glm::dvec3(0.0, 0.0, -300.0);
  return s;
}

double psnr(const std::vector<float>& a, const std::vector<float>& b) {
  double sq = 0.0;
  for (size_t i = 0; i < a.size(); ++i) sq += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
  double mse = sq / double(std::max<size_t>(a.size(), 1));
  return mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
}

double psnr(const Image& a, const std::vector<float>& reference) {
  std::vector<float> f(reference.size());
  for (size_t i = 0; i < f.size(); ++i) f[i] = float(a.rgba[(i / 3) * 4 + i % 3]) / 255.0f;
  return psnr(f, reference);
}

}  // namespace voxray::test
