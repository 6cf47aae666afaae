#include "staged_series.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <set>
#include <system_error>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>

#include "dicom/bounded_load.h"
#include "voxray/io/error.h"

namespace fs = std::filesystem;

namespace voxray::pacs {
namespace {

const char* kNothingKept = "; nothing was kept: try again, or check the node if it recurs";

std::string uid(DcmDataset& d, const DcmTagKey& tag) {
  OFString v;
  d.findAndGetOFString(tag, v);
  return v.c_str();
}

}  // namespace

StagingFolder::StagingFolder(const std::string& stagingRoot, const std::string& name) {
  std::string pattern = stagingRoot + "/" + name + "-XXXXXX";
  if (!mkdtemp(pattern.data()))
    throw outputError("Cannot create a staging folder in " + stagingRoot + " (" +
                      std::error_code(errno, std::generic_category()).message() +
                      "): free space or set VOXRAY_CACHE_DIR to a writable folder");
  path_ = pattern;
  fd_ = ::open(path_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ >= 0) ::flock(fd_, LOCK_EX | LOCK_NB);  // a fresh folder: nobody else has it
}

StagingFolder::~StagingFolder() {
  std::error_code ignored;
  if (!path_.empty()) fs::remove_all(path_, ignored);
  if (fd_ >= 0) ::close(fd_);  // releases the lock, after the folder went
}

void removeStaleStaging(const std::string& stagingRoot) {
  std::error_code ec;
  const auto youngest = fs::file_time_type::clock::now() - std::chrono::minutes(1);
  for (const auto& entry : fs::directory_iterator(stagingRoot, ec)) {
    std::error_code e;
    if (!entry.is_directory(e) || fs::last_write_time(entry.path(), e) > youngest || e) continue;
    const int fd = ::open(entry.path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) continue;
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) fs::remove_all(entry.path(), e);
    ::close(fd);
  }
}

void verifyStagedSeries(const std::string& folder, const std::string& seriesUid,
                        const std::vector<std::string>& files) {
  const std::string where = "Series " + seriesUid + ": ";
  size_t present = 0;
  std::error_code ec;
  for (auto it = fs::directory_iterator(folder, ec); !ec && it != fs::directory_iterator();
       it.increment(ec))
    ++present;
  if (files.empty() || present != files.size())
    throw inputError(where + std::to_string(files.size()) + " images were reported but " +
                     std::to_string(present) + " files arrived" + kNothingKept);
  std::set<std::string> instances;
  for (const auto& path : files) {
    DcmFileFormat file;
    const std::string name = fs::path(path).filename().string();
    std::string why = dicom::loadDicomFile(file, path, 4096, DCM_PixelData);
    DcmDataset& d = *file.getDataset();
    if (why.empty() && uid(d, DCM_SOPClassUID).empty()) why = "it has no SOP Class UID";
    const std::string series = uid(d, DCM_SeriesInstanceUID);
    if (why.empty() && series != seriesUid)
      why = "it belongs to series " + (series.empty() ? std::string("(none)") : series);
    const std::string instance = uid(d, DCM_SOPInstanceUID);
    if (why.empty() && (instance.empty() || !instances.insert(instance).second))
      why = instance.empty() ? "it has no SOP Instance UID" : "its SOP Instance UID came twice";
    if (!why.empty())
      throw inputError(where + "the node sent " + name + ", which is not an image of it (" + why +
                       ")" + kNothingKept);
  }
}

}  // namespace voxray::pacs
