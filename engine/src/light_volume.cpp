#include "light_volume.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "cl_context_impl.h"
#include "device_volume.h"
#include "voxray/engine/monte_carlo_reference.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

cl_float4 row(const glm::dmat3& m, int r) {
  return {{float(m[0][r]), float(m[1][r]), float(m[2][r]), 0.0f}};
}

}  // namespace

LightVolume::LightVolume(const Volume& v) {
  cell_ = lightGridCell(v);
  shadowOffsetMm_ = shadowOffsetMm(v);
  dims_ = (glm::max(v.dims, glm::ivec3(1)) - 1) / cell_ + 1;
  points_ = size_t(dims_.x) * size_t(dims_.y) * size_t(dims_.z);
  minSpacingMm_ = std::min({v.spacingMm.x, v.spacingMm.y, v.spacingMm.z});
}

void LightVolume::prepare(const FrameSetup& s, RaycastParams& k) const {
  const ViewGeometry& g = s.view;
  glm::dvec3 lv = g.toVoxel(g.lightWorld);
  k.light_v = {{float(lv.x), float(lv.y), float(lv.z), 0.0f}};
  glm::dmat3 toWorld = glm::inverse(g.worldToVoxel);
  k.to_world_x = row(toWorld, 0);
  k.to_world_y = row(toWorld, 1);
  k.to_world_z = row(toWorld, 2);
  k.light_grid = {{dims_.x, dims_.y, dims_.z, cell_}};
  // March one cell per step: the extinction grid holds nothing finer.
  double step = double(cell_) * minSpacingMm_;
  k.light_march = {{float(kAoRadiusMm), float(step), float(1.0 / cell_), float(shadowOffsetMm_)}};
}

bool LightVolume::update(ContextImpl& cl, const DeviceVolume& dev, const std::string& options,
                         int model, const cl::Buffer& params, const cl::Buffer& lut,
                         const RaycastParams& k, const std::vector<glm::vec4>& table) {
  // Everything the grid depends on: the model, where the table sits in stored units and its
  // opacities, the reference step, the clip box, the march; the light for shadows only.
  std::vector<float> key = {float(model),   k.values.s[2],  k.values.s[3],      k.view.s[3],
                            k.clip_lo.s[0], k.clip_lo.s[1], k.clip_lo.s[2],     k.clip_hi.s[0],
                            k.clip_hi.s[1], k.clip_hi.s[2], k.light_march.s[0], k.light_march.s[1]};
  if (model == 1) key.insert(key.end(), {k.light_v.s[0], k.light_v.s[1], k.light_v.s[2]});
  for (const glm::vec4& e : table) key.push_back(e.a);
  if (key == key_) return false;
  auto start = std::chrono::steady_clock::now();
  clCall([&] {
    if (!sigma_()) {
      sigma_ = cl::Buffer(cl.context, CL_MEM_READ_WRITE, bytes());
      grid_ = cl::Buffer(cl.context, CL_MEM_READ_WRITE, bytes());
    }
    cl_int n = cl_int(points_);
    cl::NDRange global((points_ + 63) / 64 * 64);
    cl::Kernel sigma = cl.kernel("light_volume.cl", "light_sigma", options);
    cl_uint arg = dev.setArgs(sigma, 0);
    sigma.setArg(arg++, params);
    sigma.setArg(arg++, lut);
    sigma.setArg(arg++, sigma_);
    sigma.setArg(arg, n);
    cl.queue.enqueueNDRangeKernel(sigma, cl::NullRange, global, cl::NullRange);
    cl::Kernel light =
        cl.kernel("light_volume.cl", model == 1 ? "light_shadow" : "light_ao", options);
    light.setArg(0, params);
    light.setArg(1, sigma_);
    light.setArg(2, grid_);
    light.setArg(3, n);
    cl.queue.enqueueNDRangeKernel(light, cl::NullRange, global, cl::NullRange);
    cl.queue.finish();  // the build's own time, apart from the frame's
    return 0;
  });
  lastMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  key_ = std::move(key);
  ++builds_;
  return true;
}

void LightVolume::copyInto(ContextImpl& cl, const cl::Buffer& buf, size_t offset) const {
  clCall([&] {
    cl.queue.enqueueCopyBuffer(grid_, buf, 0, offset, bytes());
    return 0;
  });
}

}  // namespace voxray
