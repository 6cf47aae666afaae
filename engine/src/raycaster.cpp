#include "voxray/engine/raycaster.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include "cl_context_impl.h"
#include "frame_setup.h"
#include "kernel_params.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

cl_float4 f4(const glm::dvec3& v, double w = 0.0) {
  return {{float(v.x), float(v.y), float(v.z), float(w)}};
}
cl_float4 f4(double x, double y, double z, double w) {
  return {{float(x), float(y), float(z), float(w)}};
}

std::string mib(size_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB"; }

}  // namespace

struct Raycaster::Impl {
  ContextImpl& cl;
  const Volume& volume;
  VolumeStorage storage;
  cl::Buffer volumeBuffer;
  cl::Image3D volumeImage;
  cl::Buffer paramsBuffer;
  cl::Buffer lutBuffer;
  size_t lutCapacity = 0;
  cl::Buffer outBuffer;
  size_t outCapacity = 0;

  Impl(ClContext& ctx, const Volume& v, VolumeStorage s) : cl(ctx.impl()), volume(v), storage(s) {}

  void upload();
  std::string options(const RenderParams& p) const;
};

void Raycaster::Impl::upload() {
  const DeviceInfo& d = cl.info;
  if (volume.voxelCount() == 0 || volume.voxels.size() != volume.voxelCount())
    throw inputError("the volume is empty or its voxel count does not match its dimensions");
  if (storage == VolumeStorage::Auto)
    storage = d.isGpu && d.imageSupport ? VolumeStorage::Image3d : VolumeStorage::Buffer;
  size_t bytes = volume.byteSize();
  std::string dims = std::to_string(volume.dims.x) + "x" + std::to_string(volume.dims.y) + "x" +
                     std::to_string(volume.dims.z);
  if (storage == VolumeStorage::Image3d) {
    if (!d.imageSupport)
      throw deviceError(d.name + " has no image support: render with the buffer storage");
    if (size_t(volume.dims.x) > d.maxImage3d[0] || size_t(volume.dims.y) > d.maxImage3d[1] ||
        size_t(volume.dims.z) > d.maxImage3d[2])
      throw deviceError("the volume (" + dims + ") exceeds " + d.name + "'s largest 3D image (" +
                        std::to_string(d.maxImage3d[0]) + "x" + std::to_string(d.maxImage3d[1]) +
                        "x" + std::to_string(d.maxImage3d[2]) + "): try --device cpu");
  }
  if (bytes > d.maxAllocBytes)
    throw deviceError("the volume (" + dims + ", " + mib(bytes) + ") exceeds " + d.name +
                      "'s largest allocation (" + mib(d.maxAllocBytes) +
                      "): crop or downsample it, or use a device with more memory");
  clCall([&] {
    if (storage == VolumeStorage::Image3d) {
      // SNORM so the hardware filters it; the kernel scales back by 32767.
      cl::ImageFormat format(CL_R, CL_SNORM_INT16);
      volumeImage = cl::Image3D(cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, format,
                                size_t(volume.dims.x), size_t(volume.dims.y), size_t(volume.dims.z),
                                0, 0, const_cast<int16_t*>(volume.voxels.data()));
    } else {
      volumeBuffer = cl::Buffer(cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bytes,
                                const_cast<int16_t*>(volume.voxels.data()));
    }
    paramsBuffer = cl::Buffer(cl.context, CL_MEM_READ_ONLY, sizeof(RaycastParams));
    return 0;
  });
}

std::string Raycaster::Impl::options(const RenderParams& p) const {
  std::ostringstream o;
  bool shading = p.shading && p.mode != Mode::Mip;
  o << "-cl-fast-relaxed-math -D MODE=" << int(p.mode) << " -D SHADING=" << int(shading)
    << " -D INTERP=" << int(p.interp)
    << " -D STORAGE_IMAGE=" << int(storage == VolumeStorage::Image3d)
    << " -D ORTHO=" << int(p.camera.projection == Projection::Orthographic);
  if (shading) o << " -D GRADIENT=" << int(p.gradient);
  if (p.mode == Mode::Iso) o << " -D REFINE_STEPS=" << p.refine;
  if (p.mode == Mode::Dvr) o << " -D OPACITY_CORRECTION=" << int(p.opacityCorrection);
  return o.str();
}

Raycaster::Raycaster(ClContext& ctx, const Volume& volume, VolumeStorage storage)
    : impl_(std::make_unique<Impl>(ctx, volume, storage)) {
  impl_->upload();
}

Raycaster::~Raycaster() = default;

VolumeStorage Raycaster::storage() const { return impl_->storage; }

std::string Raycaster::variantOptions(const RenderParams& p) const { return impl_->options(p); }

Image Raycaster::render(const RenderParams& params, FrameStats* stats) {
  Image out;
  render(params, out, stats);
  return out;
}

void Raycaster::render(const RenderParams& p, Image& out, FrameStats* stats) {
  auto start = std::chrono::steady_clock::now();
  Impl& m = *impl_;
  const Volume& v = m.volume;
  FrameSetup s = makeFrameSetup(v, p);
  const ViewGeometry& g = s.view;

  RaycastParams k{};
  k.eye_w = f4(g.eye);
  k.forward_w = f4(g.forward);
  k.right_w = f4(g.right);
  k.up_w = f4(g.up);
  k.eye_v = f4(g.toVoxel(g.eye));
  k.forward_v = f4(g.dirToVoxel(g.forward));
  k.right_v = f4(g.dirToVoxel(g.right));
  k.up_v = f4(g.dirToVoxel(g.up));
  k.clip_lo = f4(g.clipLo);
  k.clip_hi = f4(g.clipHi);
  glm::dmat3 gw = g.gradToWorld;  // glm is column-major: row r is (gw[0][r], gw[1][r], gw[2][r])
  k.grad_x = f4(gw[0][0], gw[1][0], gw[2][0], 0);
  k.grad_y = f4(gw[0][1], gw[1][1], gw[2][1], 0);
  k.grad_z = f4(gw[0][2], gw[1][2], gw[2][2], 0);
  k.light_w = f4(g.lightWorld);
  k.light = f4(p.light.ambient, p.light.diffuse, p.light.specular, p.light.shininess);
  k.background = f4(p.background);
  k.view = f4(g.halfHeight, g.aspect, s.stepMm, s.referenceStepMm);
  k.values = f4(s.isoLoStored, s.isoHiStored, s.lut.storedMin, s.lut.scale);
  k.dvr = f4(s.windowLoStored, s.windowInvWidth, p.earlyTermination, 0);
  k.dims = {{v.dims.x, v.dims.y, v.dims.z, int(s.lut.rgba.size())}};
  k.image = {{p.width, p.height, 0, 0}};

  size_t pixels = size_t(p.width) * size_t(p.height);
  out.width = p.width;
  out.height = p.height;
  out.rgba.resize(pixels * 4);
  std::string opts = m.options(p);
  cl::Kernel kernel = m.cl.kernel("raycast.cl", "raycast", opts);
  cl::Event done;
  clCall([&] {
    size_t lutBytes = s.lut.rgba.size() * sizeof(cl_float4);
    if (lutBytes > m.lutCapacity) {
      m.lutBuffer = cl::Buffer(m.cl.context, CL_MEM_READ_ONLY, lutBytes);
      m.lutCapacity = lutBytes;
    }
    if (pixels * 4 > m.outCapacity) {
      m.outBuffer = cl::Buffer(m.cl.context, CL_MEM_WRITE_ONLY, pixels * 4);
      m.outCapacity = pixels * 4;
    }
    cl::CommandQueue& q = m.cl.queue;
    q.enqueueWriteBuffer(m.paramsBuffer, CL_FALSE, 0, sizeof(k), &k);
    q.enqueueWriteBuffer(m.lutBuffer, CL_FALSE, 0, lutBytes, s.lut.rgba.data());
    if (m.storage == VolumeStorage::Image3d)
      kernel.setArg(0, m.volumeImage);
    else
      kernel.setArg(0, m.volumeBuffer);
    kernel.setArg(1, m.paramsBuffer);
    kernel.setArg(2, m.lutBuffer);
    kernel.setArg(3, m.outBuffer);
    q.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(size_t(p.width), size_t(p.height)),
                           cl::NullRange, nullptr, &done);
    q.enqueueReadBuffer(m.outBuffer, CL_TRUE, 0, pixels * 4, out.rgba.data());
    return 0;
  });
  if (stats) {
    stats->variant = opts;
    try {
      cl_ulong t0 = done.getProfilingInfo<CL_PROFILING_COMMAND_START>();
      cl_ulong t1 = done.getProfilingInfo<CL_PROFILING_COMMAND_END>();
      stats->kernelMs = double(t1 - t0) * 1e-6;
    } catch (const cl::Error&) {
      stats->kernelMs = 0.0;  // some drivers do not profile; the wall time still stands
    }
    stats->totalMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
}

}  // namespace voxray
