#include "itk_writer.h"

#include <itkMetaImageIO.h>
#include <itkNrrdImageIO.h>

#include <stdexcept>
#include <vector>

namespace voxray::test {

void writeWithItk(const Volume& v, const std::string& path, int flipAxis, bool compress) {
  const bool asIs = v.slope == 1.0 && v.intercept == 0.0;
  const bool nrrd =
      path.find(".nrrd") != std::string::npos || path.find(".nhdr") != std::string::npos;
  itk::ImageIOBase::Pointer io;
  if (nrrd)
    io = itk::NrrdImageIO::New().GetPointer();
  else
    io = itk::MetaImageIO::New().GetPointer();
  glm::dvec3 origin = v.originMm;
  glm::dmat3 direction = v.direction;
  std::vector<int16_t> data = v.voxels;
  std::vector<float> physical;
  if (flipAxis >= 0) {
    origin += direction[flipAxis] * (v.spacingMm[flipAxis] * (v.dims[flipAxis] - 1));
    direction[flipAxis] = -direction[flipAxis];
    for (int z = 0; z < v.dims.z; ++z)
      for (int y = 0; y < v.dims.y; ++y)
        for (int x = 0; x < v.dims.x; ++x) {
          glm::ivec3 from(x, y, z);
          from[flipAxis] = v.dims[flipAxis] - 1 - from[flipAxis];
          data[v.index(x, y, z)] = v.at(from.x, from.y, from.z);
        }
  }
  if (!asIs)
    for (int16_t s : data) physical.push_back(float(v.toPhysical(s)));
  io->SetNumberOfDimensions(3);
  itk::ImageIORegion region(3);
  for (unsigned a = 0; a < 3; ++a) {
    io->SetDimensions(a, itk::SizeValueType(v.dims[int(a)]));
    io->SetSpacing(a, v.spacingMm[int(a)]);
    io->SetOrigin(a, origin[int(a)]);
    const glm::dvec3 d = direction[int(a)];
    io->SetDirection(a, std::vector<double>{d.x, d.y, d.z});
    region.SetIndex(a, 0);
    region.SetSize(a, itk::SizeValueType(v.dims[int(a)]));
  }
  io->SetIORegion(region);
  io->SetComponentType(asIs ? itk::IOComponentEnum::SHORT : itk::IOComponentEnum::FLOAT);
  io->SetPixelType(itk::IOPixelEnum::SCALAR);
  io->SetNumberOfComponents(1);
  io->SetUseCompression(compress);
  io->SetFileName(path);
  try {
    io->WriteImageInformation();
    if (asIs)
      io->Write(data.data());
    else
      io->Write(physical.data());
  } catch (const itk::ExceptionObject& e) {
    throw std::runtime_error(std::string("writeWithItk: ") + e.GetDescription());
  }
}

}  // namespace voxray::test
