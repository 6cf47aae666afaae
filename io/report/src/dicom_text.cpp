#include "dicom_text.h"

#include <unistd.h>

#include <cstdio>
#include <ctime>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>

#include "voxray/io/error.h"

namespace voxray::report {

std::string newUid(const char* root) {
  char uid[100];
  dcmGenerateUniqueIdentifier(uid, root);
  return uid;
}

std::string now(const char* format) {
  char text[32];
  std::time_t t = std::time(nullptr);
  std::tm local{};
  localtime_r(&t, &local);
  std::strftime(text, sizeof text, format, &local);
  return text;
}

void saveAtomically(DcmFileFormat& file, const std::string& path, const std::string& what) {
  const std::string tmp = path + ".part" + std::to_string(getpid());
  OFCondition cond = file.saveFile(tmp.c_str(), EXS_LittleEndianExplicit);
  if (cond.bad() || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw outputError("Cannot write the " + what + " " + path + " (" +
                      (cond.bad() ? cond.text() : "rename failed") +
                      "): check the folder exists and has free space");
  }
}

}  // namespace voxray::report
