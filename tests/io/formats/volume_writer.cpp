#include "volume_writer.h"

#include <metaImage.h>
#include <teem/nrrd.h>

#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace voxray::test {
namespace {

struct Grid {
  glm::dvec3 origin;
  glm::dmat3 direction;
};

void writeNrrd(const Volume& v, const Grid& g, void* data, bool asIs, const std::string& path,
               bool compress) {
  Nrrd* n = nrrdNew();
  const size_t sizes[3] = {size_t(v.dims.x), size_t(v.dims.y), size_t(v.dims.z)};
  nrrdWrap_nva(n, data, asIs ? nrrdTypeShort : nrrdTypeFloat, 3, sizes);
  nrrdSpaceSet(n, nrrdSpaceLeftPosteriorSuperior);
  for (int a = 0; a < 3; ++a) {
    for (int r = 0; r < 3; ++r) n->axis[a].spaceDirection[r] = g.direction[a][r] * v.spacingMm[a];
    n->axis[a].kind = nrrdKindDomain;
    n->spaceOrigin[a] = g.origin[a];
  }
  NrrdIoState* io = nrrdIoStateNew();
  io->encoding = compress ? nrrdEncodingGzip : nrrdEncodingRaw;
  const int failed = nrrdSave(path.c_str(), n, io);
  nrrdIoStateNix(io);
  nrrdNix(n);  // the data belong to the caller
  if (failed) {
    char* err = biffGetDone(NRRD);
    const std::string why = err ? err : "";
    std::free(err);
    throw std::runtime_error("writeVolumeFile: " + why);
  }
}

void writeMeta(const Volume& v, const Grid& g, void* data, bool asIs, const std::string& path,
               bool compress) {
  const int dims[3] = {v.dims.x, v.dims.y, v.dims.z};
  const double spacing[3] = {v.spacingMm.x, v.spacingMm.y, v.spacingMm.z};
  MetaImage image(3, dims, spacing, asIs ? MET_SHORT : MET_FLOAT, 1, data);
  for (int a = 0; a < 3; ++a) {
    image.Position(a, g.origin[a]);
    for (int r = 0; r < 3; ++r) image.TransformMatrix(a, r, g.direction[a][r]);
  }
  image.CompressedData(compress);
  if (!image.Write(path.c_str())) throw std::runtime_error("writeVolumeFile: MetaIO failed");
}

}  // namespace

void writeVolumeFile(const Volume& v, const std::string& path, int flipAxis, bool compress) {
  const bool asIs = v.slope == 1.0 && v.intercept == 0.0;
  Grid g{v.originMm, v.direction};
  std::vector<int16_t> data(v.voxels.begin(), v.voxels.end());
  if (flipAxis >= 0) {
    g.origin += g.direction[flipAxis] * (v.spacingMm[flipAxis] * (v.dims[flipAxis] - 1));
    g.direction[flipAxis] = -g.direction[flipAxis];
    for (int z = 0; z < v.dims.z; ++z)
      for (int y = 0; y < v.dims.y; ++y)
        for (int x = 0; x < v.dims.x; ++x) {
          glm::ivec3 from(x, y, z);
          from[flipAxis] = v.dims[flipAxis] - 1 - from[flipAxis];
          data[v.index(x, y, z)] = v.at(from.x, from.y, from.z);
        }
  }
  std::vector<float> physical;
  if (!asIs)
    for (int16_t s : data) physical.push_back(float(v.toPhysical(s)));
  void* samples = asIs ? static_cast<void*>(data.data()) : static_cast<void*>(physical.data());
  const bool nrrd =
      path.find(".nrrd") != std::string::npos || path.find(".nhdr") != std::string::npos;
  if (nrrd)
    writeNrrd(v, g, samples, asIs, path, compress);
  else
    writeMeta(v, g, samples, asIs, path, compress);
}

}  // namespace voxray::test
