#include "path_test_scenes.h"

#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/raycaster.h"

namespace voxray::test {

PathImage pathRender(const Volume& v, const RenderParams& p, int spp, uint32_t seed) {
  Raycaster rc(pocl(), v);
  PathTracer pt(rc);
  PathTracerOptions o;
  o.seed = seed;
  pt.setOptions(o);
  PathImage r;
  pt.accumulate(p, spp, r.image);
  r.radiance = pt.radiance();
  return r;
}

Volume slabVolume() { return constant({8, 8, 8}, 0); }

RenderParams slabParams(double alpha, glm::dvec3 albedo) {
  RenderParams p;
  p.width = 32;
  p.height = 24;
  p.mode = Mode::Dvr;
  p.lighting = Lighting::Cinematic;
  p.camera.projection = Projection::Orthographic;
  p.transferFunction = {{-1000.0, glm::dvec4(albedo, alpha)}, {1000.0, glm::dvec4(albedo, alpha)}};
  p.background = glm::dvec3(1.0);
  return p;
}

Volume shadowVolume() {
  Volume v = constant({16, 16, 16}, 0);
  for (int z = 0; z < 16; ++z)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x)
        v.voxels[v.index(x, y, z)] = int16_t(z < 10 ? 500 : z < 12 ? -1000 : 1000);
  return v;
}

RenderParams shadowParams(double diffuse) {
  RenderParams p = slabParams(0.0, glm::dvec3(0.0));
  p.background = glm::dvec3(0.0);
  glm::dvec4 air(0.0), block(1.0, 1.0, 1.0, 0.3), slab(0.0, 0.0, 0.0, 1.0);
  p.transferFunction = {{-1000.0, air}, {0.0, air},    {0.0, block},
                        {750.0, block}, {750.0, slab}, {1000.0, slab}};
  p.light.followCamera = false;
  p.light.position = glm::dvec3(0.0, 0.0, 1e30);
  p.light.diffuse = diffuse;
  p.light.ambient = 0.3;
  return p;
}

Volume ballVolume() { return ball({16, 16, 16}, 5.0); }

RenderParams ballParams() {
  RenderParams p;
  p.width = 16;
  p.height = 12;
  p.mode = Mode::Dvr;
  p.lighting = Lighting::Cinematic;
  p.camera.azimuthDeg = 30.0;
  p.camera.elevationDeg = 20.0;
  p.transferFunction = {{-1000.0, glm::dvec4(0.0)},
                        {0.0, glm::dvec4(0.9, 0.6, 0.5, 0.05)},
                        {1000.0, glm::dvec4(0.9, 0.8, 0.7, 0.4)}};
  p.background = glm::dvec3(0.1, 0.1, 0.2);
  p.light.ambient = 0.3;
  p.light.diffuse = 0.8;
  return p;
}

}  // namespace voxray::test
