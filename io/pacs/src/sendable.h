#pragma once
// What C-STORE and STOW-RS send: regular files that parse as DICOM with their SOP Class and
// SOP Instance UIDs, checked before anything is sent. A FIFO would block the send, a device
// (/dev/zero) would be read without end, and any other file would go out as if it were DICOM.
#include <memory>
#include <string>
#include <vector>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcfilefo.h>

namespace voxray::pacs {

struct SendableFile {
  std::string path;
  std::shared_ptr<const std::string> bytes;  // the whole file, as read once
  std::unique_ptr<DcmFileFormat> dicom;      // parsed from BYTES
};

// Reads and checks every file; throws Input naming the first that is not sendable (and that
// nothing was sent).
std::vector<SendableFile> loadSendableFiles(const std::vector<std::string>& paths);

}  // namespace voxray::pacs
