#include "metaimage_read.h"

#include <itkMetaImageIO.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "voxray/io/error.h"

namespace voxray::formats {
namespace {

using Component = itk::IOComponentEnum;

constexpr KindCodes kItkTypes = {
    int(Component::UCHAR), int(Component::CHAR), int(Component::USHORT), int(Component::SHORT),
    int(Component::UINT),  int(Component::INT),  int(Component::FLOAT),  int(Component::DOUBLE)};

// The acronym MetaIO writers derive from the directions (ITK's convention: the side each axis
// comes from, "RAI" for L, P, S), to compare with the file's AnatomicalOrientation.
std::string orientationAcronym(const glm::dmat3& direction) {
  std::string code;
  for (int a = 0; a < 3; ++a) {
    const glm::dvec3 d = direction[a];
    const int c = std::abs(d.x) >= std::abs(d.y) && std::abs(d.x) >= std::abs(d.z) ? 0
                  : std::abs(d.y) >= std::abs(d.z)                                 ? 1
                                                                                   : 2;
    static const char from[3][2] = {{'R', 'L'}, {'A', 'P'}, {'I', 'S'}};
    code += from[c][d[c] < 0 ? 1 : 0];
  }
  return code;
}

void checkAnatomicalOrientation(SampleGrid& g, itk::MetaImageIO& io) {
  const char* given = io.GetMetaImagePointer()->AnatomicalOrientationAcronym();
  const std::string file = given ? given : "";
  if (file.size() < 3 || file.find('?') != std::string::npos) return;
  const std::string matrix = orientationAcronym(g.direction);
  if (file.substr(0, 3) != matrix)
    g.warnings.push_back("the header's AnatomicalOrientation (" + file.substr(0, 3) +
                         ") disagrees with its TransformMatrix (" + matrix +
                         "); the TransformMatrix is used, as ITK and 3D Slicer do");
}

// A detached data file that is not there: said plainly before MetaIO tries it (MetaIO's own
// failure there also leaks the stream it opened).
void checkDataFile(const std::string& path, itk::MetaImageIO& io) {
  const std::string data = io.GetMetaImagePointer()->ElementDataFileName();
  if (data.empty() || data == "LOCAL" || data == "Local" || data == "local" ||
      data.find_first_of("% ") != std::string::npos || data.rfind("LIST", 0) == 0)
    return;  // inline data, or a list or pattern of slice files that MetaIO resolves itself
  const std::filesystem::path file = std::filesystem::path(path).parent_path() / data;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(data, ec) && !std::filesystem::is_regular_file(file, ec))
    throw inputError(path + ": its data file " + data +
                     " is missing; keep the .mhd and its data file in one folder");
}

// Reads the header and every sample; the caller keeps the first 3D volume and component.
SampleGrid read(const std::string& path) {
  itk::MetaImageIO::Pointer io = itk::MetaImageIO::New();
  if (!io->CanReadFile(path.c_str()))
    throw inputError(path + ": not a readable MetaImage file (its header is missing or damaged)");
  io->SetFileName(path);
  io->ReadImageInformation();
  const unsigned n = io->GetNumberOfDimensions();
  if (n < 2)
    throw inputError(path + ": holds a " + std::to_string(n) + "D image; Voxray opens volumes");
  SampleGrid g;
  uint64_t extra = io->GetNumberOfComponents();
  glm::dmat3 steps(0.0);
  for (unsigned a = 0; a < n; ++a) {
    if (a >= 3) {
      extra *= std::max<uint64_t>(io->GetDimensions(a), 1);
      continue;
    }
    g.dims[a] = io->GetDimensions(a);
    const std::vector<double> d = io->GetDirection(a);
    for (unsigned r = 0; r < 3 && r < d.size(); ++r)
      steps[int(a)][int(r)] = d[r] * io->GetSpacing(a);
    g.originMm[int(a)] = io->GetOrigin(a);
  }
  if (n == 2) {
    g.dims[2] = 1;
    steps[2] = glm::cross(steps[0], steps[1]);
    steps[2] /= glm::length(steps[2]);  // one slice: thickness 1 mm along the normal
  }
  checkDims(g.dims, extra, path);
  setAxes(g, steps, path);
  if (!std::isfinite(g.originMm.x + g.originMm.y + g.originMm.z))
    throw inputError(path + ": the origin in the header is not a number; the file is damaged");
  checkAnatomicalOrientation(g, *io);
  checkDataFile(path, *io);
  g.decoding.kind =
      kindOfCode(kItkTypes, int(io->GetComponentType()),
                 itk::ImageIOBase::GetComponentTypeAsString(io->GetComponentType()), path);
  g.sourceType = kindName(g.decoding.kind);

  itk::ImageIORegion region(n);
  for (unsigned a = 0; a < n; ++a) {
    region.SetIndex(a, 0);
    region.SetSize(a, io->GetDimensions(a));
  }
  io->SetIORegion(region);
  const size_t total = size_t(io->GetImageSizeInBytes());
  auto buffer = std::shared_ptr<uint8_t[]>(new uint8_t[total]);
  io->Read(buffer.get());

  const unsigned components = io->GetNumberOfComponents();
  const uint64_t volumes = extra / components;
  if (components > 1) {
    // Keep component 0 of each voxel, packed in place.
    const size_t s = detail::sampleBytes(g.decoding.kind);
    const size_t count = g.dims[0] * g.dims[1] * g.dims[2];
    for (size_t i = 1; i < count; ++i)
      std::memmove(buffer.get() + i * s, buffer.get() + i * components * s, s);
    g.warnings.push_back("each voxel holds " + std::to_string(components) +
                         " values (a vector or list axis); the first is shown");
  }
  if (volumes > 1)
    g.warnings.push_back("the file holds " + std::to_string(volumes) +
                         " volumes (4D: time points, phases or diffusion directions); this is " +
                         "volume 1 of " + std::to_string(volumes));
  g.samples = buffer.get();
  g.storage = std::move(buffer);
  return g;
}

}  // namespace

SampleGrid readMetaImage(const std::string& path) {
  try {
    return read(path);
  } catch (const itk::ExceptionObject& e) {
    // ITK's text names its source file and line; keep only its description.
    const std::string what = e.GetDescription();
    throw inputError(path + ": cannot be read (" + what +
                     "); the file or its data file is damaged, truncated or missing");
  } catch (const std::bad_alloc&) {
    throw inputError(path + ": not enough memory to read this volume");
  }
}

}  // namespace voxray::formats
