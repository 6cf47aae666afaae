#include "metaimage_read.h"

#include <metaImage.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>

#include "voxray/io/error.h"

namespace voxray::formats {
namespace {

constexpr KindCodes kMetaTypes = {MET_UCHAR, MET_CHAR, MET_USHORT, MET_SHORT,
                                  MET_UINT,  MET_INT,  MET_FLOAT,  MET_DOUBLE};

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

void checkAnatomicalOrientation(SampleGrid& g, const MetaImage& image) {
  const char* given = image.AnatomicalOrientationAcronym();
  const std::string file = given ? given : "";
  if (file.size() < 3 || file.find('?') != std::string::npos) return;
  const std::string matrix = orientationAcronym(g.direction);
  if (file.substr(0, 3) != matrix)
    g.warnings.push_back("the header's AnatomicalOrientation (" + file.substr(0, 3) +
                         ") disagrees with its TransformMatrix (" + matrix +
                         "); the TransformMatrix is used, as ITK and 3D Slicer do");
}

// A detached data file that is not there: said plainly before MetaIO tries it (MetaIO's own
// failure there is vague and leaks the stream it opened).
void checkDataFile(const std::string& path, const MetaImage& image) {
  const std::string data = image.ElementDataFileName();
  if (data.empty() || data == "LOCAL" || data == "Local" || data == "local" ||
      data.find_first_of("% ") != std::string::npos || data.rfind("LIST", 0) == 0)
    return;  // inline data, or a list or pattern of slice files that MetaIO resolves itself
  const std::filesystem::path file = std::filesystem::path(path).parent_path() / data;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(data, ec) && !std::filesystem::is_regular_file(file, ec))
    throw inputError(path + ": its data file " + data +
                     " is missing; keep the .mhd and its data file in one folder");
}

}  // namespace

SampleGrid readMetaImage(const std::string& path) {
  MetaImage image;
  if (!image.Read(path.c_str(), false))
    throw inputError(path + ": not a readable MetaImage file (its header is missing or damaged)");
  const int n = image.NDims();
  if (n < 2 || n > 10)
    throw inputError(path + ": holds a " + std::to_string(n) + "D image; Voxray opens volumes");
  SampleGrid g;
  uint64_t extra = uint64_t(std::max(image.ElementNumberOfChannels(), 1));
  glm::dmat3 steps(0.0);
  for (int a = 0; a < n; ++a) {
    if (image.DimSize(a) < 1)
      throw inputError(path + ": the header gives a dimension of size " +
                       std::to_string(image.DimSize(a)) + "; the file is damaged");
    if (a >= 3) {
      extra *= uint64_t(image.DimSize(a));
      continue;
    }
    g.dims[size_t(a)] = uint64_t(image.DimSize(a));
    for (int r = 0; r < 3 && r < n; ++r)
      steps[a][r] = image.TransformMatrix(a, r) * image.ElementSpacing(a);
    g.originMm[a] = image.Position(a);
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
  checkAnatomicalOrientation(g, image);
  g.decoding.kind = kindOfCode(kMetaTypes, image.ElementType(),
                               "MetaImage type " + std::to_string(int(image.ElementType())), path);
  g.sourceType = kindName(g.decoding.kind);
  checkDataFile(path, image);

  const size_t channels = size_t(std::max(image.ElementNumberOfChannels(), 1));
  const size_t s = detail::sampleBytes(g.decoding.kind);
  const size_t count = g.dims[0] * g.dims[1] * g.dims[2];
  auto buffer = std::shared_ptr<uint8_t[]>(new uint8_t[count * s * extra]);
  MetaImage full;
  if (!full.Read(path.c_str(), true, buffer.get()))
    throw inputError(path + ": the data cannot be read; the file or its data file is damaged, " +
                     "truncated or missing");
  if (channels > 1) {  // keep channel 0 of each voxel, packed in place
    for (size_t i = 1; i < count; ++i)
      std::memmove(buffer.get() + i * s, buffer.get() + i * channels * s, s);
    g.warnings.push_back("each voxel holds " + std::to_string(channels) +
                         " values (a vector or list axis); the first is shown");
  }
  if (extra / channels > 1)
    g.warnings.push_back("the file holds " + std::to_string(extra / channels) +
                         " volumes (4D: time points, phases or diffusion directions); this is " +
                         "volume 1 of " + std::to_string(extra / channels));
  g.samples = buffer.get();
  g.storage = std::move(buffer);
  return g;
}

}  // namespace voxray::formats
