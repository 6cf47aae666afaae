#include "nrrd_read.h"

#include <teem/nrrd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>

#include "nrrd_header_check.h"
#include "teem_handles.h"
#include "voxray/io/error.h"

namespace voxray::formats {
namespace {

using teem::IoNix;
using teem::NrrdNuke;
using teem::reason;

constexpr KindCodes kNrrdTypes = {nrrdTypeUChar, nrrdTypeChar, nrrdTypeUShort, nrrdTypeShort,
                                  nrrdTypeUInt,  nrrdTypeInt,  nrrdTypeFloat,  nrrdTypeDouble};

// Sign of each world axis when it becomes LPS; zero for spaces without anatomical meaning.
glm::dvec3 toLps(int space) {
  switch (space) {
    case nrrdSpaceRightAnteriorSuperior:
    case nrrdSpaceRightAnteriorSuperiorTime:
      return {-1, -1, 1};
    case nrrdSpaceLeftAnteriorSuperior:
    case nrrdSpaceLeftAnteriorSuperiorTime:
      return {1, -1, 1};
    case nrrdSpaceLeftPosteriorSuperior:
    case nrrdSpaceLeftPosteriorSuperiorTime:
      return {1, 1, 1};
    default:
      return {0, 0, 0};
  }
}

struct Layout {
  unsigned axes[3] = {0, 0, 0};  // the nrrd axes of i, j, k
  unsigned spatial = 0;          // how many of them exist (2 or 3)
  size_t components = 1;         // values per voxel (a range axis that is the fastest)
  uint64_t volumes = 1;          // product of the axes after k
};

Layout layoutOf(const Nrrd& n, const std::string& path) {
  Layout l;
  unsigned domain[NRRD_DIM_MAX];
  const unsigned count = nrrdDomainAxesGet(&n, domain);
  if (count < 2) throw inputError(path + ": has fewer than two spatial axes; Voxray opens volumes");
  l.spatial = std::min(count, 3u);
  for (unsigned a = 0; a < l.spatial; ++a) l.axes[a] = domain[a];
  for (unsigned a = 0; a < n.dim; ++a) {
    const bool spatial = a == l.axes[0] || a == l.axes[1] || (l.spatial == 3 && a == l.axes[2]);
    if (spatial) continue;
    if (a == 0)
      l.components = n.axis[0].size;
    else if (a > l.axes[l.spatial - 1])
      l.volumes *= n.axis[a].size;
    else
      throw inputError(path + ": a non-spatial axis lies between the spatial ones (axis " +
                       std::to_string(a) + "); Voxray cannot pick one volume from that layout");
  }
  return l;
}

void setGeometry(SampleGrid& g, const Nrrd& n, const Layout& l, const std::string& path) {
  const glm::dvec3 sign = toLps(n.space);
  const bool anatomical = sign != glm::dvec3(0.0);
  if (n.spaceDim > 0 && !anatomical)
    g.warnings.push_back(std::string("the file's space is \"") + airEnumStr(nrrdSpace, n.space) +
                         "\", which does not name patient directions; its axes are taken as "
                         "left, posterior, superior (check left and right)");
  if (n.spaceDim == 0)
    g.warnings.push_back(
        "the file gives spacings but no space directions: orientation "
        "unknown, axes taken as left, posterior, superior (check left and right)");
  const glm::dvec3 s = anatomical ? sign : glm::dvec3(1.0);
  glm::dmat3 steps(0.0);
  for (unsigned a = 0; a < l.spatial; ++a) {
    double spacing = NAN;
    double dir[NRRD_SPACE_DIM_MAX] = {0};
    const int status = nrrdSpacingCalculate(&n, l.axes[a], &spacing, dir);
    if (status == nrrdSpacingStatusDirection) {
      steps[int(a)] = glm::dvec3(dir[0], dir[1], n.spaceDim > 2 ? dir[2] : 0.0) * s * spacing;
    } else if (status == nrrdSpacingStatusScalarNoSpace || status == nrrdSpacingStatusNone) {
      steps[int(a)][int(a)] = status == nrrdSpacingStatusNone ? 1.0 : spacing;
    } else {
      throw inputError(path + ": the spacing of axis " + std::to_string(l.axes[a]) +
                       " cannot be worked out (damaged or contradictory header)");
    }
  }
  if (l.spatial == 2) steps[2] = glm::normalize(glm::cross(steps[0], steps[1]));
  setAxes(g, steps, path);
  g.originMm = glm::dvec3(0.0);
  if (n.spaceDim > 0 && !std::isnan(n.spaceOrigin[0])) {
    g.originMm =
        glm::dvec3(n.spaceOrigin[0], n.spaceOrigin[1], n.spaceDim > 2 ? n.spaceOrigin[2] : 0.0) *
            s +
        glm::dvec3(0.0);  // + 0: no -0 in JSON output
    if (!std::isfinite(g.originMm.x + g.originMm.y + g.originMm.z))
      throw inputError(path + ": the space origin is not a number; the file is damaged");
  }
}

// True when PATH's first line is a NRRD magic ("NRRD000" and a version digit, then the end
// of the line). Teem, given anything else, tries its other formats and leaks its line buffer
// on the way (libFuzzer's leak check found it), so such files are refused before Teem opens
// them.
bool hasNrrdMagic(const std::string& path) {
  char magic[10] = {};
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  const size_t got = f ? std::fread(magic, 1, sizeof magic, f.get()) : 0;
  return got >= 9 && std::memcmp(magic, "NRRD000", 7) == 0 && magic[7] >= '1' && magic[7] <= '9' &&
         (magic[8] == '\n' || (magic[8] == '\r' && magic[9] == '\n'));
}

// Teem read the data-file field as checkNrrdHeader did (the same files, or the same pattern):
// anything else would open files that were not checked.
bool sameDataFiles(const NrrdDataFiles& d, const NrrdIoState& io) {
  if (io.dataFNFormat)
    return d.format == io.dataFNFormat && d.first == io.dataFNMin && d.last == io.dataFNMax &&
           d.step == io.dataFNStep;
  if (!d.format.empty() || d.names.size() != io.dataFNArr->len) return false;
  for (size_t i = 0; i < d.names.size(); ++i)
    if (d.names[i] != io.dataFN[i]) return false;
  return true;
}

}  // namespace

SampleGrid readNrrd(const std::string& path) {
  if (!hasNrrdMagic(path))
    throw inputError(
        path +
        ": not a readable NRRD file (it does not start with a NRRD0001 ... NRRD0009 line); "
        "check the file or its name ending");
  const NrrdDataFiles files = checkNrrdHeader(path);
  // Absolute: Teem finds detached data files in the folder of the path it is given, which is
  // then the folder checkNrrdHeader resolved them in.
  const std::string absolute = std::filesystem::absolute(path).string();
  // The header first: sizes are checked before Teem allocates what they claim.
  std::unique_ptr<Nrrd, NrrdNuke> header(nrrdNew());
  std::unique_ptr<NrrdIoState, IoNix> io(nrrdIoStateNew());
  io->skipData = 1;
  if (nrrdLoad(header.get(), absolute.c_str(), io.get()))
    throw inputError(path + ": not a readable NRRD file (" + reason() + ")");
  if (!sameDataFiles(files, *io))
    throw inputError(path + ": its data file field reads differently than Voxray checked it; " +
                     "the header is damaged");
  const Nrrd& h = *header;
  const Layout l = layoutOf(h, path);
  SampleGrid g;
  for (unsigned a = 0; a < 3; ++a) g.dims[a] = a < l.spatial ? h.axis[l.axes[a]].size : 1;
  checkDims(g.dims, l.components * l.volumes, path);
  g.decoding.kind = kindOfCode(kNrrdTypes, h.type, airEnumStr(nrrdType, h.type), path);
  g.sourceType = kindName(g.decoding.kind);
  setGeometry(g, h, l, path);
  if (l.components > 1)
    g.warnings.push_back("each voxel holds " + std::to_string(l.components) +
                         " values (a vector or list axis); the first is shown");
  if (l.volumes > 1)
    g.warnings.push_back("the file holds " + std::to_string(l.volumes) +
                         " volumes (4D: time points, phases or diffusion directions); this is " +
                         "volume 1 of " + std::to_string(l.volumes));

  if (!files.files.empty() && io->encoding == nrrdEncodingRaw) {
    const uint64_t bytes = uint64_t(nrrdElementNumber(&h)) * nrrdElementSize(&h);
    checkNrrdDataFileSizes(files, bytes / files.files.size(),
                           io->lineSkip > 0 || io->byteSkip != 0 || io->dataFSkip, path);
  }

  std::unique_ptr<Nrrd, NrrdNuke> full(nrrdNew());
  if (nrrdLoad(full.get(), absolute.c_str(), nullptr))
    throw inputError(path + ": the data cannot be read (" + reason() +
                     "); the file or its data file is damaged, truncated or missing");
  auto* data = static_cast<uint8_t*>(full->data);
  full->data = nullptr;  // adopted below: no copy of the volume
  g.storage = std::shared_ptr<void>(data, std::free);
  if (l.components > 1) {
    const size_t s = detail::sampleBytes(g.decoding.kind);
    const size_t count = g.dims[0] * g.dims[1] * g.dims[2];
    for (size_t i = 1; i < count; ++i) std::memmove(data + i * s, data + i * l.components * s, s);
  }
  g.samples = data;
  return g;
}

}  // namespace voxray::formats
