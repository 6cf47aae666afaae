#pragma once
// The orbit camera turned into rays. "World" is patient LPS in mm with the origin at
// the volume's centre; "voxel" coordinates have voxel centres at integers, so the
// volume's box is [-0.5, n - 0.5] along each axis. Both renderers take their rays here.
#include <glm/glm.hpp>

#include "voxray/engine/render_params.h"

namespace voxray {

struct Volume;

struct ViewGeometry {
  bool orthographic = false;
  glm::dvec3 eye{0.0};                           // world
  glm::dvec3 forward{0.0}, right{0.0}, up{0.0};  // world, orthonormal
  double halfHeight = 1.0;  // view plane half height: tan(fov/2)/zoom, or mm for ortho
  double aspect = 1.0;      // width / height
  glm::dmat3 worldToVoxel{1.0};
  glm::dvec3 voxelCentre{0.0};          // voxel coordinates of the world origin
  glm::dmat3 gradToWorld{1.0};          // voxel-index gradient -> gradient per mm in world
  glm::dvec3 clipLo{0.0}, clipHi{0.0};  // clip box in voxel coordinates
  glm::dvec3 lightWorld{0.0};

  // Ray through the centre of pixel (px, py) of a width x height image; dir is unit length
  // in world, so the ray parameter is in mm.
  void ray(int px, int py, int width, int height, glm::dvec3& originWorld,
           glm::dvec3& dirWorld) const;
  glm::dvec3 toVoxel(const glm::dvec3& world) const { return worldToVoxel * world + voxelCentre; }
  glm::dvec3 dirToVoxel(const glm::dvec3& dirWorld) const { return worldToVoxel * dirWorld; }
};

ViewGeometry makeViewGeometry(const Volume& v, const RenderParams& p);

// Ray/box intersection (slab method) in voxel coordinates. Returns false when the ray
// misses; zero direction components are handled without dividing by zero.
bool intersectBox(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& lo,
                  const glm::dvec3& hi, double& tEnter, double& tExit, int& enterAxis);

}  // namespace voxray
