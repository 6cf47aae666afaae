#pragma once
// The device side of the shadows and ao lighting models (kernels/lighting/light_volume.cl): a
// coarse grid of the classified volume's extinction and, from it, each grid point's transmittance
// toward the light (shadows) or ambient visibility (ao). Rebuilt only when what it depends
// on changes (the model, the table's opacities, the clip box, the light for shadows), never
// for a camera move alone; the raycaster copies it behind the table in the table's buffer,
// where the shading reads it (kernels/shading/shading.cl, frame_light).
#include <string>
#include <vector>

#include <CL/opencl.hpp>

#include "frame_setup.h"
#include "kernel_params.h"

namespace voxray {

struct ContextImpl;
class DeviceVolume;

class LightVolume {
 public:
  // The grid for a volume of these dimensions (a point every cell() voxels).
  explicit LightVolume(const Volume& v);
  // Fills k's lighting fields for a frame (before k is uploaded).
  void prepare(const FrameSetup& s, RaycastParams& k) const;
  // Rebuilds the grid on the device when the frame k (enqueued in params, its table in lut)
  // needs another; model is the LIGHTING switch (1 shadows, 2 ao), `options` compiles
  // light_volume.cl for the volume's storage. iso: the frame is iso, whose occluder is its
  // iso range (k.values.x .. y), not the table. Returns whether it rebuilt; then lastMs() is
  // the wall time of the build (kernel compilation included the first time). leap: the
  // frame's macro-cell occupancy when it follows this table's opacities (dvr with empty-space
  // skipping), so that empty cells are not read; else nullptr. holdLight: keep a grid that
  // differs from the frame's only by the light (Raycaster::holdLightGrid, a drag) while that
  // light is within kHeldLightDeg of the grid's, seen from the volume's centre.
  bool update(ContextImpl& cl, const DeviceVolume& dev, const std::string& options, int model,
              bool iso, const cl::Buffer& params, const cl::Buffer& lut, const cl::Buffer* leap,
              const RaycastParams& k, const std::vector<glm::vec4>& table, bool holdLight);
  // Copies the grid into buf at byte offset (the raycaster's table buffer, behind the table).
  void copyInto(ContextImpl& cl, const cl::Buffer& buf, size_t offset) const;
  size_t bytes() const { return points_ * sizeof(float); }
  int cell() const { return cell_; }
  int builds() const { return builds_; }
  int sigmaBuilds() const { return sigmaBuilds_; }
  int heldFrames() const { return heldFrames_; }
  double lastMs() const { return lastMs_; }

 private:
  // shadows: the axis to sweep the grid along slice by slice (light_sweep), or -1 where the
  // light lies within the grid's extent on every axis (then each point marches, light_shadow).
  int sweepAxis(const RaycastParams& k) const;

  glm::ivec3 dims_{0};
  int cell_ = 1;
  size_t points_ = 0;
  double minSpacingMm_ = 1.0, shadowOffsetMm_ = 1.0;
  glm::dvec3 spacingMm_{1.0}, centre_{0.0};  // centre: the volume's, in voxels
  cl::Buffer sigma_, lattice_, grid_;
  // What the grid and its sigma were built for, the light apart (shadows only); equal keys
  // skip the work.
  std::vector<float> key_, lightKey_, sigmaKey_;
  int builds_ = 0, sigmaBuilds_ = 0, heldFrames_ = 0;
  double lastMs_ = 0.0;
};

}  // namespace voxray
