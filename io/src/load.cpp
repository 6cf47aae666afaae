#include "voxray/io/load.h"

#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "file_kind.h"
#include "raw_messages.h"
#include "voxray/io/error.h"
#include "voxray/io/phantom.h"
#include "voxray/io/sample_volume.h"

#if __has_include("voxray/io/dicom_import.h") && defined(VOXRAY_HAS_DICOM)
#include "voxray/io/dicom_import.h"
#define VOXRAY_LOAD_DICOM 1
#endif
#include "voxray/io/ome_zarr.h"
#include "voxray/io/volume_file.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

// True unless the file surely is not DICOM: Part 10 files carry "DICM" after a 128-byte
// preamble; older ACR-NEMA style files start straight with a group 0002 or 0008 tag.
bool mayBeDicom(const fs::path& file) {
  if (file.filename() == "DICOMDIR") return true;
  std::ifstream in(file, std::ios::binary);
  if (!in) throw inputError(file.string() + ": cannot read the file (check its permissions)");
  std::array<unsigned char, 132> head{};
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  const auto got = size_t(in.gcount());
  if (got == head.size() && std::memcmp(head.data() + 128, "DICM", 4) == 0) return true;
  if (got < 8) return false;
  const unsigned groupLittle = head[0] | (head[1] << 8), groupBig = (head[0] << 8) | head[1];
  return groupLittle == 0x0002 || groupLittle == 0x0008 || groupBig == 0x0008;
}

// Inputs with one time point take --time 0 only.
void refuseTimePoint(const std::string& input, const LoadOptions& options) {
  if (options.timePoint && *options.timePoint != 0)
    throw inputError((input.empty() ? std::string("the head phantom") : input) + ": --time " +
                     std::to_string(*options.timePoint) +
                     " is out of range: it has 1 time point (4D is read from DICOM and NIfTI)");
}

}  // namespace

Volume loadVolume(const std::string& input, const LoadOptions& options) {
  if (input.empty() || input == kSampleCtInput || options.raw) refuseTimePoint(input, options);
  if (input.empty()) return makeHeadPhantom();
  if (input == kSampleCtInput) return loadSampleCt();
  if (options.raw) return importRaw(input, *options.raw, {options.progress, options.cancel});

  std::error_code ec;
  // A URL is read by the network library (loadVolumeOrUrl, voxray/io/zarr_url.h); this path has
  // none. No credentials: the message names the scheme only.
  if (input.rfind("http://", 0) == 0 || input.rfind("https://", 0) == 0)
    throw inputError(input.substr(0, input.find(':')) +
                     " URL: only the main input of voxray-cli and the workstation may be a URL "
                     "(an OME-Zarr); give a local file or folder here");
  if (!fs::exists(input, ec)) throw inputError(input + ": no such file or folder");
  detail::refuseSpecialFile(input);
  if (options.level != 0 && !isOmeZarr(input))
    throw inputError(input + ": --level " + std::to_string(options.level) +
                     " picks a level of an OME-Zarr pyramid; this input has one resolution");
  if (isOmeZarr(input)) {
#if defined(VOXRAY_HAS_ZARR)
    refuseTimePoint(input, options);
    return importOmeZarr(input, options);
#else
    throw inputError(input + ": this build of Voxray cannot read OME-Zarr (it was built with " +
                     "VOXRAY_WITH_ZARR=OFF)");
#endif
  }
  if (isVolumeFile(input)) {
#if defined(VOXRAY_HAS_FORMATS)
    return importVolumeFile(input, options);
#else
    throw inputError(input + ": this build of Voxray cannot read NIfTI, NRRD or MetaImage (it " +
                     "was built with VOXRAY_WITH_FORMATS=OFF)");
#endif
  }
  if (fs::is_regular_file(input, ec) && !mayBeDicom(input)) {
    throw inputError(input + ": not a DICOM file; " + detail::kRawUsage);
  }
#ifdef VOXRAY_LOAD_DICOM
  return importDicom(input, options);
#else
  throw inputError(input + ": this build of Voxray cannot read DICOM (it was built without " +
                   "DCMTK); " + detail::kRawUsage);
#endif
}

std::vector<Volume> loadVolumeSeries(const std::string& input, const LoadOptions& options) {
  LoadOptions first = options;
  first.timePoint.reset();
#ifdef VOXRAY_LOAD_DICOM
  std::error_code ec;
  if (!input.empty() && input != kSampleCtInput && !options.raw && !isVolumeFile(input) &&
      !isOmeZarr(input) && fs::exists(input, ec) &&
      (!fs::is_regular_file(input, ec) || mayBeDicom(input)))
    return importDicomTimePoints(input, first);
#endif
  std::vector<Volume> out;
  out.push_back(loadVolume(input, first));
  for (int t = 1; t < out.front().timePoints; ++t) {
    LoadOptions next = first;
    next.timePoint = t;
    out.push_back(loadVolume(input, next));
  }
  return out;
}

}  // namespace voxray

// Unity builds: the next file of a batch must not see it.
#undef VOXRAY_LOAD_DICOM
