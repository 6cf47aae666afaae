#include "sendable.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include <dcmtk/dcmdata/dcdeftag.h>

#include "dicom/bounded_load.h"
#include "voxray/io/error.h"

namespace voxray::pacs {
namespace {

const char* kNothingSent = "; nothing was sent";

std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  return "not a plain file";
}

// The whole file, read through one descriptor whose type was checked: a path swapped for a
// FIFO between a check and an open must not block here (O_NONBLOCK, fstat).
std::shared_ptr<const std::string> readRegularFile(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0)
    throw inputError(path + ": cannot read (" +
                     std::error_code(errno, std::generic_category()).message() + ")" +
                     kNothingSent);
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(fd);
    throw inputError(path + " is " + kindOf(info.st_mode) +
                     ", not a regular file: give DICOM files" + kNothingSent);
  }
  auto bytes = std::make_shared<std::string>(size_t(info.st_size), '\0');
  size_t done = 0;
  while (done < bytes->size()) {
    const ssize_t n = ::pread(fd, bytes->data() + done, bytes->size() - done, off_t(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += size_t(n);
  }
  ::close(fd);
  bytes->resize(done);  // a file that shrank meanwhile: what was there (the parse judges it)
  return bytes;
}

}  // namespace

std::vector<SendableFile> loadSendableFiles(const std::vector<std::string>& paths) {
  std::vector<SendableFile> files;
  for (const auto& path : paths) {
    SendableFile f{path, readRegularFile(path), std::make_unique<DcmFileFormat>()};
    std::string why = dicom::loadDicomBytes(*f.dicom, f.bytes);
    OFString sopClass, sopInstance;
    DcmDataset* d = f.dicom->getDataset();
    if (why.empty() && (d->findAndGetOFString(DCM_SOPClassUID, sopClass).bad() ||
                        d->findAndGetOFString(DCM_SOPInstanceUID, sopInstance).bad() ||
                        sopClass.empty() || sopInstance.empty()))
      why = "it has no SOP Class UID or SOP Instance UID";
    if (!why.empty())
      throw inputError(path + " is not a DICOM file Voxray can send (" + why + ")" + kNothingSent);
    files.push_back(std::move(f));
  }
  return files;
}

}  // namespace voxray::pacs
