#include "voxray/io/dicom_write.h"

#include <cstdio>
#include <ctime>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>

#include "voxray/io/error.h"
#include "voxray/io/temporary_file.h"

namespace voxray::dicomwrite {

std::string newUid(const char* root) {
  char uid[100];
  dcmGenerateUniqueIdentifier(uid, root);
  return uid;
}

std::string localNow(const char* format) {
  char text[32];
  std::time_t t = std::time(nullptr);
  std::tm local{};
  localtime_r(&t, &local);
  std::strftime(text, sizeof text, format, &local);
  return text;
}

void saveAtomically(DcmFileFormat& file, const std::string& path, const std::string& what,
                    Encoding encoding) {
  const std::string tmp = temporaryBeside(path).string();
  const OFCondition cond = encoding == Encoding::explicitLittleEndian
                               ? file.saveFile(tmp.c_str(), EXS_LittleEndianExplicit)
                               : file.saveFile(tmp.c_str(), EXS_Unknown, EET_ExplicitLength,
                                               EGL_recalcGL, EPD_noChange, 0, 0, EWM_createNewMeta);
  if (cond.bad() || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw outputError("Cannot write the " + what + " " + path + " (" +
                      (cond.bad() ? cond.text() : "rename failed") +
                      "): check the folder exists, is writable and has free space");
  }
}

}  // namespace voxray::dicomwrite
