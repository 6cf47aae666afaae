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

// light_sweep's slices per interpolation of the transmittance (the depth between is summed
// at each slice): fewer interpolations blur the shadow less (32.2 dB with 1, 32.6 dB with 4 or 8
// on the sphere above a plane).
constexpr int kSweepReach = 4;
// The most march steps (points x the grid's dimensions summed, a bound of each point's
// steps) for which shadows marches per point rather than sweeping: 48x48x40 voxels marches,
// CThead and the 512x512x400 CT sweep.
constexpr double kMarchSteps = 16.0 * 1024 * 1024;
// The most a held grid's light may have turned (seen from the volume's centre) before a drag
// frame rebuilds it: a held grid's shadows are those of a light fixed to the anatomy where the
// drag started, and past ~45 degrees that is further from the converged frame than no
// shadows at all (CThead CT-Bone dvr, bench --drag on PoCL: 44.5, 36.5, 29.6, 24.5 dB at 10,
// 30, 60, 90 degrees against phong's 31.7-32.3 dB; the ball above a plane 33.1 and 27.1 dB
// at 10 and 30 against 18.9-19.5). So a drag rebuilds once per 45 degrees (22 of the 3D
// view's 2-degree frames) and its error stays that of 45 degrees at worst.
constexpr double kHeldLightDeg = 45.0;

// Sets a kernel's arguments from the first, in order.
template <class... Args>
void setArgs(cl::Kernel& kernel, const Args&... args) {
  cl_uint i = 0;
  (kernel.setArg(i++, args), ...);
}

cl_float4 row(const glm::dmat3& m, int r) {
  return {{float(m[0][r]), float(m[1][r]), float(m[2][r]), 0.0f}};
}

}  // namespace

LightVolume::LightVolume(const Volume& v) {
  cell_ = lightGridCell(v);
  shadowOffsetMm_ = shadowOffsetMm(v);
  dims_ = (glm::max(v.dims, glm::ivec3(1)) - 1) / cell_ + 1;
  points_ = size_t(dims_.x) * size_t(dims_.y) * size_t(dims_.z);
  minSpacingMm_ = v.minSpacingMm();
  spacingMm_ = v.spacingMm;
  centre_ = 0.5 * (glm::dvec3(glm::max(v.dims, glm::ivec3(1))) - 1.0);
}

namespace {

// The angle (degrees) between lights A and B (voxel positions) seen from C, in mm.
double turnDeg(const std::vector<float>& a, const std::vector<float>& b, glm::dvec3 c,
               glm::dvec3 spacingMm) {
  if (a.size() != 3 || b.size() != 3) return 180.0;
  const glm::dvec3 u = (glm::dvec3(a[0], a[1], a[2]) - c) * spacingMm;
  const glm::dvec3 w = (glm::dvec3(b[0], b[1], b[2]) - c) * spacingMm;
  const double n = glm::length(u) * glm::length(w);
  if (!(n > 0.0) || !std::isfinite(n)) return 180.0;
  return glm::degrees(std::acos(std::clamp(glm::dot(u, w) / n, -1.0, 1.0)));
}

}  // namespace

int LightVolume::sweepAxis(const RaycastParams& k) const {
  // Valid along an axis when the light lies a cell or more beyond the grid's end slices
  // there: then every point's step toward the light crosses to the slice before. Of those,
  // the axis the light lies farthest along (mm from the centre) keeps the steps steepest.
  int best = -1;
  double bestMm = 0.0;
  for (int a = 0; a < 3; ++a) {
    double l = k.light_v.s[a], last = double(dims_[a] - 1) * cell_;
    if (!std::isfinite(l) || (l > -cell_ && l < last + cell_)) continue;
    double mm = std::abs(l - 0.5 * last) * spacingMm_[a];
    if (mm > bestMm) best = a, bestMm = mm;
  }
  return best;
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
                         int model, bool iso, const cl::Buffer& params, const cl::Buffer& lut,
                         const cl::Buffer* leap, const RaycastParams& k,
                         const std::vector<glm::vec4>& table, bool holdLight) {
  // What the sigma grid depends on: the reference step, the clip box, and for iso the iso
  // range, else where the table sits in stored units and its opacities; the grid then adds
  // the model and the march, and the light for shadows only.
  std::vector<float> sigmaKey = {float(iso),     k.view.s[3],    k.clip_lo.s[0], k.clip_lo.s[1],
                                 k.clip_lo.s[2], k.clip_hi.s[0], k.clip_hi.s[1], k.clip_hi.s[2]};
  if (iso) {
    sigmaKey.insert(sigmaKey.end(), {k.values.s[0], k.values.s[1]});
  } else {
    sigmaKey.insert(sigmaKey.end(), {k.values.s[2], k.values.s[3]});
    for (const glm::vec4& e : table) sigmaKey.push_back(e.a);
  }
  std::vector<float> key = {float(model), k.light_march.s[0], k.light_march.s[1]};
  std::vector<float> lightKey;
  if (model == 1) lightKey = {k.light_v.s[0], k.light_v.s[1], k.light_v.s[2]};
  bool sigmaKept = sigmaKey == sigmaKey_;
  if (sigmaKept && key == key_) {
    if (lightKey == lightKey_) return false;
    if (holdLight && turnDeg(lightKey, lightKey_, centre_, spacingMm_) <= kHeldLightDeg) {
      // A drag: the grid of the light it was built for.
      ++heldFrames_;
      return false;
    }
  }
  auto start = std::chrono::steady_clock::now();
  clCall([&] {
    if (!sigma_()) {
      sigma_ = cl::Buffer(cl.context, CL_MEM_READ_WRITE, bytes());
      grid_ = cl::Buffer(cl.context, CL_MEM_READ_WRITE, bytes());
      lattice_ = cl::Buffer(cl.context, CL_MEM_READ_WRITE, bytes());
    }
    cl_int n = cl_int(points_);
    cl::NDRange global((points_ + 63) / 64 * 64);
    if (!sigmaKept) {  // a light or model change alone keeps it
      cl::Kernel sigma = cl.kernel("lighting/light_volume.cl", "light_sigma", options);
      cl_uint arg = dev.setArgs(sigma, 0);  // vol, or vol0 .. per slab
      sigma.setArg(arg++, params);
      sigma.setArg(arg++, lut);
      sigma.setArg(arg++, leap ? *leap : sigma_);  // unread without use_leap
      sigma.setArg(arg++, cl_int(leap != nullptr));
      sigma.setArg(arg++, cl_int(iso));
      sigma.setArg(arg++, sigma_);
      sigma.setArg(arg, n);
      cl.queue.enqueueNDRangeKernel(sigma, cl::NullRange, global, cl::NullRange);
      ++sigmaBuilds_;
    }
    // A kernel (params, from, grid, points) over the grid's points.
    auto perPoint = [&](const char* name, const cl::Buffer& from) {
      cl::Kernel kernel = cl.kernel("lighting/light_volume.cl", name, options);
      setArgs(kernel, params, from, grid_, n);
      cl.queue.enqueueNDRangeKernel(kernel, cl::NullRange, global, cl::NullRange);
    };
    // A small grid marches each point toward the light: exact along the ray, where the
    // sweep's interpolation each few slices blurs the shadow (2.8 dB on the sphere above a
    // plane, lighting_kernel_test.cpp).
    bool march = double(points_) * double(dims_.x + dims_.y + dims_.z) <= kMarchSteps;
    int axis = model == 1 && !march ? sweepAxis(k) : -1;
    if (model == 1 && axis >= 0) {
      // One work-group sweeps every slice (barriers between them): as large as the device
      // allows, up to a slice's points.
      cl::Kernel sweep = cl.kernel("lighting/light_volume.cl", "light_sweep", options);
      setArgs(sweep, params, sigma_, grid_, cl_int(axis), cl_int(k.light_v.s[axis] > 0.0f ? 1 : -1),
              cl_int(kSweepReach));
      size_t across = size_t(dims_[(axis + 1) % 3]) * size_t(dims_[(axis + 2) % 3]);
      size_t items = sweep.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(cl.device);
      items = std::max<size_t>(1, std::min({items, size_t(1024), across}));
      cl.queue.enqueueNDRangeKernel(sweep, cl::NullRange, cl::NDRange(items), cl::NDRange(items));
    } else if (model == 1) {  // the light within the grid's extent: march per point
      perPoint("light_shadow", sigma_);
    } else {
      // ao at every other point per axis where that lattice stays within the radius (ao
      // is smooth over it): 1/8 of the marches, then filled in.
      int every = 2.0 * cell_ * minSpacingMm_ <= kAoRadiusMm ? 2 : 1;
      glm::ivec3 m = (dims_ - 1) / every + 1;
      cl_int4 lattice = {{m.x, m.y, m.z, 0}};
      size_t count = size_t(m.x) * size_t(m.y) * size_t(m.z);
      cl::Buffer& target = every > 1 ? lattice_ : grid_;
      cl::Kernel ao = cl.kernel("lighting/light_volume.cl", "light_ao", options);
      setArgs(ao, params, sigma_, target, lattice, cl_int(every));
      cl.queue.enqueueNDRangeKernel(ao, cl::NullRange, cl::NDRange((count + 63) / 64 * 64),
                                    cl::NullRange);
      if (every > 1) {
        cl::Kernel fill = cl.kernel("lighting/light_volume.cl", "light_ao_fill", options);
        setArgs(fill, params, lattice_, grid_, lattice, cl_int(every));
        cl.queue.enqueueNDRangeKernel(fill, cl::NullRange, global, cl::NullRange);
      }
    }
    cl.queue.finish();  // the build's own time, apart from the frame's
    return 0;
  });
  lastMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  sigmaKey_ = std::move(sigmaKey);
  key_ = std::move(key);
  lightKey_ = std::move(lightKey);
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
