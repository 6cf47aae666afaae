#include "nifti_read.h"

#include "nifti_header_check.h"
#include "nifti_hints.h"

#include <nifti2_io.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>

#include "voxray/io/error.h"

namespace voxray::formats {
namespace {

struct NiftiFree {
  void operator()(nifti_image* n) const { nifti_image_free(n); }
};
using NiftiPtr = std::unique_ptr<nifti_image, NiftiFree>;

constexpr KindCodes kNiftiTypes = {DT_UINT8,  DT_INT8,  DT_UINT16,  DT_INT16,
                                   DT_UINT32, DT_INT32, DT_FLOAT32, DT_FLOAT64};

// Millimetres per unit of the file's xyz_units (unknown: millimetres, as NIfTI tools assume).
double mmPerUnit(int units) {
  switch (XYZT_TO_SPACE(units)) {
    case NIFTI_UNITS_METER:
      return 1000.0;
    case NIFTI_UNITS_MICRON:
      return 0.001;
    default:
      return 1.0;
  }
}

bool orthogonal(const glm::dmat3& d) {
  const double tol = 1e-4;
  return std::abs(glm::dot(d[0], d[1])) < tol && std::abs(glm::dot(d[0], d[2])) < tol &&
         std::abs(glm::dot(d[1], d[2])) < tol;
}

// Index-to-LPS steps and origin of one NIfTI affine (RAS+): x and y change sign.
void applyAffine(SampleGrid& g, const nifti_dmat44& a, double mm, const std::string& path) {
  glm::dmat3 steps;
  for (int c = 0; c < 3; ++c) steps[c] = glm::dvec3(-a.m[0][c], -a.m[1][c], a.m[2][c]) * mm;
  setAxes(g, steps, path);
  g.originMm = glm::dvec3(-a.m[0][3], -a.m[1][3], a.m[2][3]) * mm + glm::dvec3(0.0);  // no -0
  if (!std::isfinite(g.originMm.x + g.originMm.y + g.originMm.z))
    throw inputError(path + ": the origin in the header is not a number; the file is damaged");
}

void chooseGeometry(SampleGrid& g, const nifti_image& n, const std::string& path) {
  const double mm = mmPerUnit(n.xyz_units);
  if (n.sform_code > 0) {
    applyAffine(g, n.sto_xyz, mm, path);
    if (orthogonal(g.direction)) return;
    if (n.qform_code <= 0)
      throw inputError(path + ": the sform is sheared (its axes are not at right angles) and " +
                       "there is no qform; Voxray shows rectangular grids only (resample it)");
    g.warnings.push_back("the sform is sheared (axes not at right angles); the qform is used");
  } else if (n.qform_code <= 0) {
    g.warnings.push_back(
        "the header has neither sform nor qform: orientation unknown, axes "
        "taken as right, anterior, superior (check left and right)");
  }
  applyAffine(g, n.qto_xyz, mm, path);  // the library builds it from pixdim when not set
}

// The library allocates the whole volume before it reads a byte: a header claiming 13 GB in
// a 600-byte file must be refused first. Deflate expands at most about 1032:1, which bounds
// what a .nii.gz can hold.
void checkDataFits(const std::string& path, const nifti_image& n, uint64_t volumeBytes) {
  std::error_code ec;
  const uint64_t have = n.iname ? std::filesystem::file_size(n.iname, ec) : 0;
  if (ec) throw inputError(path + ": its image data file cannot be read (" + ec.message() + ")");
  const bool gz = nifti_is_gzfile(n.iname) != 0;
  const uint64_t offset = uint64_t(std::max<int64_t>(n.iname_offset, 0));
  const uint64_t holds = gz ? have * 1032 : (have > offset ? have - offset : 0);
  if (volumeBytes > holds)
    throw inputError(path + ": the image data is shorter than the header says (it claims " +
                     std::to_string(volumeBytes) + " bytes; the file has " + std::to_string(have) +
                     (gz ? ", compressed" : "") + "); the file is damaged or truncated");
}

}  // namespace

SampleGrid readNifti(const std::string& path, int timePoint) {
  nifti_set_debug_level(0);  // the library would print to stderr; our messages say it all
  if (const std::string problem = niftiHeaderProblem(path); !problem.empty())
    throw inputError(path + ": not a readable NIfTI file (" + problem + ")");
  NiftiPtr header(nifti_image_read(path.c_str(), 0));
  if (!header)
    throw inputError(path + ": not a readable NIfTI file (the header is missing, truncated or " +
                     "invalid)");
  const nifti_image& n = *header;
  SampleGrid g;
  for (int a = 1; a <= 7; ++a)
    if (n.dim[a] < 1 && a <= n.dim[0])
      throw inputError(path + ": the header gives dimension " + std::to_string(a) + " a size of " +
                       std::to_string(n.dim[a]) + "; the file is damaged");
  g.dims = {uint64_t(n.nx), uint64_t(n.dim[0] >= 2 ? n.ny : 1), uint64_t(n.dim[0] >= 3 ? n.nz : 1)};
  uint64_t volumes = 1;
  for (int a = 4; a <= n.dim[0] && a <= 7; ++a) {
    if (volumes > (uint64_t(1) << 40) / uint64_t(n.dim[a]))
      throw inputError(path + ": the header claims an impossible number of volumes");
    volumes *= uint64_t(n.dim[a]);
  }
  checkDims(g.dims, volumes, path);
  g.decoding.kind = kindOfCode(kNiftiTypes, n.datatype, nifti_datatype_string(n.datatype), path);
  g.sourceType = kindName(g.decoding.kind);
  if (n.scl_slope != 0.0 && std::isfinite(n.scl_slope) && std::isfinite(n.scl_inter)) {
    g.decoding.slope = n.scl_slope;
    g.decoding.intercept = n.scl_inter;
  }
  chooseGeometry(g, n, path);
  // The library ends both with a NUL; strnlen keeps a damaged one from running on.
  const ValueHint hint =
      niftiValueHint(std::string(n.descrip, strnlen(n.descrip, sizeof n.descrip)),
                     std::string(n.intent_name, strnlen(n.intent_name, sizeof n.intent_name)));
  g.modality = hint.modality;
  if (!hint.unit.empty()) g.unit = hint.unit;
  if (timePoint < 0 || uint64_t(timePoint) >= volumes)
    throw inputError(path + ": --time " + std::to_string(timePoint) +
                     " is out of range: the file has " + std::to_string(volumes) +
                     " time point(s)" +
                     (volumes > 1 ? ", 0 to " + std::to_string(volumes - 1) : std::string()));
  g.timePoint = timePoint;
  g.timePoints = int(volumes);
  if (volumes > 1)
    g.warnings.push_back("the file holds " + std::to_string(volumes) +
                         " volumes (4D: time points, phases or diffusion directions); this is " +
                         "volume " + std::to_string(timePoint + 1) + " of " +
                         std::to_string(volumes) + " (time point " + std::to_string(timePoint) +
                         "; --time chooses another)");

  checkDataFits(path, n, g.dims[0] * g.dims[1] * g.dims[2] * detail::sampleBytes(g.decoding.kind));
  // Only the chosen 3D volume is read (a 4D file can be many times larger).
  const int64_t first[1] = {timePoint};
  nifti_brick_list bricks{};
  NiftiPtr data(nifti_image_read_bricks(path.c_str(), 1, first, &bricks));
  if (!data || bricks.nbricks != 1 || !bricks.bricks || !bricks.bricks[0]) {
    if (data) nifti_free_NBL(&bricks);
    throw inputError(path + ": the image data is shorter than the header says or is damaged " +
                     "(truncated download or copy?); get the file again");
  }
  const size_t bytes = g.dims[0] * g.dims[1] * g.dims[2] * detail::sampleBytes(g.decoding.kind);
  if (size_t(bricks.bsize) < bytes) {
    nifti_free_NBL(&bricks);
    throw inputError(path + ": the image data is shorter than the header says");
  }
  // The brick is malloc'ed by the library: adopt it instead of copying a whole volume.
  g.storage = std::shared_ptr<void>(bricks.bricks[0], std::free);
  g.samples = static_cast<const uint8_t*>(g.storage.get());
  bricks.bricks[0] = nullptr;
  nifti_free_NBL(&bricks);
  return g;
}

}  // namespace voxray::formats
