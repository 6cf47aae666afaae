#include "staged_series.h"

#include <fcntl.h>
#include <linux/fs.h>
#include <sys/file.h>
#include <sys/ioctl.h>
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

void spreadNewFolders(const std::string& stagingRoot) {
  const int fd = ::open(stagingRoot.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  int flags = 0;
  if (::ioctl(fd, FS_IOC_GETFLAGS, &flags) == 0 && !(flags & FS_TOPDIR_FL)) {
    flags |= FS_TOPDIR_FL;
    ::ioctl(fd, FS_IOC_SETFLAGS, &flags);  // a hint: where it is refused, nothing changes
  }
  ::close(fd);
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

namespace {

// Why the parsed file (WHY: the parser's reason, if any) is not an image of SERIES_UID;
// INSTANCE gets its SOP Instance UID.
std::string notAnImage(std::string why, DcmFileFormat& file, const std::string& seriesUid,
                       std::string& instance) {
  DcmDataset& d = *file.getDataset();
  if (why.empty() && uid(d, DCM_SOPClassUID).empty()) why = "it has no SOP Class UID";
  const std::string series = uid(d, DCM_SeriesInstanceUID);
  if (why.empty() && series != seriesUid)
    why = "it belongs to series " + (series.empty() ? std::string("(none)") : series);
  instance = uid(d, DCM_SOPInstanceUID);
  if (why.empty() && instance.empty()) why = "it has no SOP Instance UID";
  return why;
}

}  // namespace

void SeriesCheck::arrived(const std::string& path, const std::string& bytes) {
  DcmFileFormat file;
  Checked c;
  c.why = notAnImage(dicom::loadDicomHeader(file, bytes.data(), bytes.size(), DCM_PixelData), file,
                     seriesUid_, c.instance);
  arrived_[path] = std::move(c);
}

void SeriesCheck::known(const std::string& path, const std::string& sopClassUid,
                        const std::string& seriesUid, const std::string& sopInstanceUid) {
  // notAnImage's verdicts, in its order, for a file that parsed.
  Checked c;
  if (sopClassUid.empty())
    c.why = "it has no SOP Class UID";
  else if (seriesUid != seriesUid_)
    c.why = "it belongs to series " + (seriesUid.empty() ? std::string("(none)") : seriesUid);
  else if (sopInstanceUid.empty())
    c.why = "it has no SOP Instance UID";
  c.instance = sopInstanceUid;
  arrived_[path] = std::move(c);
}

SeriesCheck::Checked SeriesCheck::check(const std::string& path) const {
  if (auto it = arrived_.find(path); it != arrived_.end()) return it->second;
  DcmFileFormat file;
  Checked c;
  c.why = notAnImage(dicom::loadDicomFile(file, path, 4096, DCM_PixelData), file, seriesUid_,
                     c.instance);
  return c;
}

void SeriesCheck::verify(const std::string& folder, const std::vector<std::string>& files) const {
  const std::string where = "Series " + seriesUid_ + ": ";
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
    Checked c = check(path);
    if (c.why.empty() && !instances.insert(c.instance).second)
      c.why = "its SOP Instance UID came twice";
    if (!c.why.empty())
      throw inputError(where + "the node sent " + fs::path(path).filename().string() +
                       ", which is not an image of it (" + c.why + ")" + kNothingKept);
  }
}

void verifyStagedSeries(const std::string& folder, const std::string& seriesUid,
                        const std::vector<std::string>& files) {
  SeriesCheck(seriesUid).verify(folder, files);
}

}  // namespace voxray::pacs
