#include "device_frame.h"

#include "voxray/io/volume.h"

namespace voxray {

namespace {

cl_float4 f4(const glm::dvec3& v, double w = 0.0) {
  return {{float(v.x), float(v.y), float(v.z), float(w)}};
}
cl_float4 f4(double x, double y, double z, double w) {
  return {{float(x), float(y), float(z), float(w)}};
}

}  // namespace

void DeviceFrame::upload(size_t maxSlabBytes) {
  const DeviceInfo& d = cl.info;
  if (volume.voxelCount() == 0 || volume.voxels.size() != volume.voxelCount())
    throw inputError("the volume is empty or its voxel count does not match its dimensions");
  if (storage == VolumeStorage::Auto)
    storage = d.isGpu && d.imageSupport ? VolumeStorage::Image3d : VolumeStorage::Buffer;
  device.upload(cl, volume, storage, maxSlabBytes);
  clCall([&] {
    paramsBuffer = cl::Buffer(cl.context, CL_MEM_READ_ONLY, sizeof(RaycastParams));
    return 0;
  });
}

void DeviceFrame::updateSetup(const RenderParams& p, bool preint) {
  SetupKey key = setupKeyOf(p);
  if (key != setupKey) {
    if (!valueRange) valueRange = storedRange(volume);
    setup = makeValueSetup(volume, key, *valueRange);
    setupKey = std::move(key);
  }
  placeFrame(setup, volume, p);
  if (!preint) {
    setup.preint = {};
    return;
  }
  // Opacity correction makes the table's opacities those of the step; without it they stay
  // the table's, as for one sample.
  double ratio = p.opacityCorrection ? setup.stepMm / setup.referenceStepMm : 1.0;
  if (setup.preint.empty() || setup.preint.ratio != ratio)
    setup.preint = bakePreintTable(setup.lut, ratio);
}

RaycastParams DeviceFrame::frameParams(const RenderParams& p, const KernelSwitches& sw) const {
  const Volume& v = volume;
  const FrameSetup& s = setup;
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
  k.dvr =
      f4(s.windowLoStored, s.windowInvWidth, p.earlyTermination, sw.ADAPTIVE ? p.adaptiveError : 0);
  k.dims = {{v.dims.x, v.dims.y, v.dims.z, int(s.lut.rgba.size())}};
  k.image = {{p.width, p.height, 0, 0}};
  if (sw.GRADIENT_OPACITY)
    k.gradient_opacity = f4(s.gradient.scale, double(s.gradient.factor.size()) - 1.0, 0, 0);
  if (sw.TF2D) k.tf2d = f4(s.tf2d.storedLo, s.tf2d.perStored, s.tf2d.perStoredPerMm, 0);
  if (sw.PREINT) k.preint = f4(s.preint.storedLo, s.preint.perStored, 0, 0);
  packSwitches(sw, k);
  k.slabs = {{device.plan().depth, 0, 0, 0}};
  return k;
}

size_t DeviceFrame::tableBytes() const {
  return setup.lut.rgba.size() * sizeof(cl_float4) + setup.gradient.factor.size() * sizeof(float) +
         setup.tf2d.rgba.size() * sizeof(cl_float4) + setup.preint.rgba.size() * sizeof(cl_float4);
}

void DeviceFrame::uploadFrame(const RaycastParams& k, size_t extraBytes) {
  size_t lutBytes = setup.lut.rgba.size() * sizeof(cl_float4), bytes = tableBytes() + extraBytes;
  if (bytes > lutCapacity) {
    lutBuffer = cl::Buffer(cl.context, CL_MEM_READ_ONLY, bytes);
    lutCapacity = bytes;
    lutUploaded.clear();
    gradientUploaded.clear();
    tf2dUploaded.clear();
    preintUploaded.clear();
    ++lutAllocations;
  }
  cl::CommandQueue& q = cl.queue;
  paramsUploaded = k;  // the asynchronous write reads this copy, which outlives the caller's
  q.enqueueWriteBuffer(paramsBuffer, CL_FALSE, 0, sizeof(k), &paramsUploaded);
  if (setup.lut.rgba != lutUploaded) {
    lutUploaded = setup.lut.rgba;  // the asynchronous write reads this copy
    q.enqueueWriteBuffer(lutBuffer, CL_FALSE, 0, lutBytes, lutUploaded.data());
  }
  if (setup.gradient.factor != gradientUploaded) {
    gradientUploaded = setup.gradient.factor;
    if (!gradientUploaded.empty())
      q.enqueueWriteBuffer(lutBuffer, CL_FALSE, lutBytes, gradientUploaded.size() * sizeof(float),
                           gradientUploaded.data());
  }
  // The 2D table (never with the gradient's: setupKeyOf keeps one of them) behind the colour
  // table, where tf2d.cl reads it.
  if (setup.tf2d.rgba != tf2dUploaded) {
    tf2dUploaded = setup.tf2d.rgba;
    if (!tf2dUploaded.empty())
      q.enqueueWriteBuffer(lutBuffer, CL_FALSE, lutBytes + gradientUploaded.size() * sizeof(float),
                           tf2dUploaded.size() * sizeof(cl_float4), tf2dUploaded.data());
  }
  // The pre-integrated table (never with the other two: PREINT is not set with them) likewise.
  if (setup.preint.rgba != preintUploaded) {
    preintUploaded = setup.preint.rgba;
    if (!preintUploaded.empty())
      q.enqueueWriteBuffer(lutBuffer, CL_FALSE,
                           lutBytes + gradientUploaded.size() * sizeof(float) +
                               tf2dUploaded.size() * sizeof(cl_float4),
                           preintUploaded.size() * sizeof(cl_float4), preintUploaded.data());
  }
}

}  // namespace voxray
