#pragma once
// Text from DICOM headers as UTF-8. Strings are stored in the dataset's
// SpecificCharacterSet (ISO_IR 100 for most European data, GB18030, ISO 2022 with code
// extensions, ...); Voxray converts them before they reach JSON, the UI or a message.
#include <string>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcitem.h>
#include <dcmtk/dcmdata/dcspchrs.h>

namespace voxray::dicom {

class TextDecoder {
 public:
  // Reads SpecificCharacterSet (0008,0005) of DATASET; none means the default repertoire.
  explicit TextDecoder(DcmItem& dataset);

  // RAW as valid UTF-8: converted from the dataset's character set; bytes that still do not
  // decode (a damaged file, an undeclared character set) become U+FFFD. PERSON_NAME: RAW is
  // a PN value, whose components also end ISO 2022 code extensions (PS3.5 6.1.2.5.3).
  std::string operator()(const std::string& raw, bool personName = false) const;

 private:
  mutable DcmSpecificCharacterSet converter_;
  bool convert_ = false;
  // Japanese ISO 2022 (IR 87, IR 159), which DCMTK's glibc iconv back end does not map:
  // the whole value is then ISO-2022-JP-2, which glibc's iconv reads directly.
  bool japanese2022_ = false;
};

// TEXT with every byte sequence that is not UTF-8 replaced by U+FFFD.
std::string validUtf8(const std::string& text);

}  // namespace voxray::dicom
