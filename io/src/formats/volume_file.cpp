// NIfTI, NRRD and MetaImage into a Volume: the readers (nifti_read, nrrd_read, metaimage_read) hand
// over a grid of samples in LPS; here it is checked and fitted into 16-bit voxels exactly as raw
// input is (raw_samples: exact when the values fit int16, else a slope that keeps precision).
#include "voxray/io/volume_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "../consumed_pages.h"
#include "../file_kind.h"
#include "metaimage_read.h"
#include "nifti_read.h"
#include "nrrd_read.h"
#include "voxray/io/error.h"
#include "voxray/io/parallel.h"
#include "voxray/io/raw_import.h"

namespace fs = std::filesystem;

namespace voxray {
namespace formats {

std::string kindName(detail::SampleKind kind) {
  static const char* const names[] = {"u8", "i8", "u16", "i16", "u32", "i32", "f32", "f64"};
  return names[int(kind)];
}

detail::SampleKind kindOfCode(const KindCodes& codes, int code, const std::string& typeName,
                              const std::string& path) {
  for (size_t k = 0; k < codes.size(); ++k)
    if (codes[k] == code) return detail::SampleKind(k);
  throw inputError(path + ": holds " + typeName +
                   " samples; Voxray opens scalar u8, i8, u16, i16, u32, i32, f32 and f64 " +
                   "volumes (convert it to one of those)");
}

void setAxes(SampleGrid& g, const glm::dmat3& stepsLps, const std::string& path) {
  static const char* const axis[] = {"i (first)", "j (second)", "k (third)"};
  for (int a = 0; a < 3; ++a) {
    const double length = glm::length(stepsLps[a]);
    if (!std::isfinite(length) || length <= 0.0)
      throw inputError(path + ": the header gives the " + axis[a] + " axis " +
                       (std::isfinite(length) ? "a zero direction or spacing"
                                              : "a spacing or direction that is not a number") +
                       "; the file is damaged (its geometry cannot be shown in millimetres)");
    g.spacingMm[a] = length;
    g.direction[a] = stepsLps[a] / length + glm::dvec3(0.0);  // + 0: no -0 in JSON output
  }
  if (std::abs(glm::determinant(g.direction)) < 1e-3)
    throw inputError(path + ": the header's axis directions are parallel; the file is damaged");
}

void checkDims(const std::array<uint64_t, 3>& dims, uint64_t extra, const std::string& path) {
  uint64_t count = 1;
  for (uint64_t d : dims) {
    if (d == 0)
      throw inputError(path + ": the header gives a dimension of size 0; nothing to show");
    if (d > uint64_t(INT32_MAX) || count > kMaxVoxels / d)
      throw inputError(path + ": the header claims more voxels than Voxray can hold (at most " +
                       std::to_string(kMaxVoxels) + "); the file is damaged or too large");
    count *= d;
  }
  if (extra == 0 || extra > (uint64_t(1) << 40) / count)
    throw inputError(path + ": the header claims an impossible number of values per voxel or " +
                     "volumes; the file is damaged");
}

std::string dataFileInFolder(const std::string& path, const std::string& name,
                             const std::string& candidate) {
  const std::string where = path + ": its data file '" + name + "'";
  std::string resolved;
  switch (detail::placeInFolder(fs::absolute(path).parent_path().string(), candidate, &resolved)) {
    case detail::Placement::Inside:
      return resolved;
    case detail::Placement::Missing:
      throw inputError(where + " is missing; keep the header and its data files in one folder");
    case detail::Placement::Outside:
      throw inputError(where +
                       " lies outside the header's folder (after links are followed); "
                       "Voxray reads only data files in the header's folder: move them there");
    case detail::Placement::NotRegular:
      break;
  }
  throw inputError(where + " is not a regular file (a folder, FIFO or device); the header is " +
                   "damaged");
}

}  // namespace formats

namespace {

// PATH ends in one of volumeFileExtensions(): ".gz" can only be ".nii.gz".
formats::SampleGrid readGrid(const std::string& path, int timePoint) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".nii" || ext == ".gz") return formats::readNifti(path, timePoint);
  if (timePoint != 0)
    throw inputError(path + ": --time " + std::to_string(timePoint) +
                     " is out of range: the file has 1 time point (Voxray reads 4D from NIfTI "
                     "and DICOM)");
  if (ext == ".nrrd" || ext == ".nhdr") return formats::readNrrd(path);
  return formats::readMetaImage(path);
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Whole values that fit int16 are stored as they are (raw input's rule, raw_samples.h). Integer
// samples whose file rescale (NIfTI scl_slope/scl_inter) makes fractions keep the file's own
// scale when the samples fit int16, exact as the DICOM import keeps RescaleSlope; anything
// else follows raw input's rule (a power-of-two step, with a warning).
detail::Storage storageFor(const detail::ValueStats& stats, const detail::SampleDecoding& d) {
  const bool rescaled = d.slope != 1.0 || d.intercept != 0.0;
  // A denormal slope (a damaged header) has no finite inverse: chooseStorage picks one.
  if (isIntegerKind(d.kind) && rescaled && stats.any && !stats.integral &&
      std::isfinite(1.0 / d.slope)) {
    const double a = (stats.min - d.intercept) / d.slope, b = (stats.max - d.intercept) / d.slope;
    if (std::min(a, b) >= -32768.5 && std::max(a, b) <= 32767.5) {
      detail::Storage keep;
      keep.slope = d.slope;
      keep.intercept = d.intercept;
      keep.fill = stats.min;
      keep.warning = "values are fractional; they are stored with the file's own scale (slope " +
                     number(d.slope) + ", intercept " + number(d.intercept) + "), exactly";
      return keep;
    }
  }
  return detail::chooseStorage(stats, d);
}

void report(const LoadOptions& o, double fraction, const std::string& what) {
  if (o.progress) o.progress(fraction, what);
}

void throwIfCancelled(const LoadOptions& o) {
  if (o.cancel && o.cancel->load()) throw cancelledError("loading cancelled");
}

}  // namespace

Volume importVolumeFile(const std::string& path, const LoadOptions& options) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw inputError(path + ": no such file");
  detail::refuseSpecialFile(path);
  if (fs::is_directory(path, ec))
    throw inputError(path + ": is a folder, not a volume file; open a file inside it");
  if (fs::file_size(path, ec) == 0 && !ec)
    throw inputError(path + ": the file is empty (0 bytes); it was not saved completely");
  report(options, 0.0, "Reading " + fs::path(path).filename().string());
  formats::SampleGrid g = readGrid(path, options.timePoint.value_or(0));
  throwIfCancelled(options);

  // Slices are scanned, then stored, in parallel; the value range decides the storage.
  const size_t sliceVoxels = g.dims[0] * g.dims[1];
  const size_t sliceBytes = sliceVoxels * detail::sampleBytes(g.decoding.kind);
  const size_t slices = g.dims[2];
  std::vector<detail::ValueStats> stats(slices);
  report(options, 0.6, "Checking the value range");
  parallelFor(
      slices,
      [&](size_t k) {
        stats[k] = detail::scanSamples(g.samples + k * sliceBytes, sliceVoxels, g.decoding);
      },
      options.cancel);
  throwIfCancelled(options);
  detail::ValueStats all;
  for (const auto& s : stats) all.merge(s);
  const detail::Storage storage = storageFor(all, g.decoding);

  Volume v;
  v.dims = glm::ivec3(int(g.dims[0]), int(g.dims[1]), int(g.dims[2]));
  v.spacingMm = g.spacingMm;
  v.originMm = g.originMm;
  v.direction = g.direction;
  v.slope = storage.slope;
  v.intercept = storage.intercept;
  v.unit = g.unit;
  v.modality = g.modality;
  v.sourceType = g.sourceType;
  v.timePoint = g.timePoint;
  v.timePoints = g.timePoints;
  v.warnings = g.warnings;
  if (!storage.warning.empty()) v.warnings.push_back(storage.warning);
  if (!isIntegerKind(g.decoding.kind) && storage.slope != 1.0 && storage.warning.empty())
    v.warnings.push_back("values are fractional; they are stored with a step of " +
                         number(storage.slope) + " (up to 65536 levels over their range)");
  v.voxels.resize(v.voxelCount());
  report(options, 0.8, "Converting to 16-bit voxels");
  parallelFor(
      slices,
      [&](size_t k) {
        detail::storeSamples(g.samples + k * sliceBytes, sliceVoxels, g.decoding, storage,
                             v.voxels.data() + k * sliceVoxels);
        // The reader's buffer is the grid's own and read once: each slice's pages go as it
        // is stored, so the peak is the volume once, not the file's samples beside it.
        detail::releaseConsumedPages(g.samples + k * sliceBytes, sliceBytes);
      },
      options.cancel);
  throwIfCancelled(options);
  report(options, 1.0, "Loaded");
  return v;
}

}  // namespace voxray
