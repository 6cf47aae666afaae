#include "private_tags.h"

#include <dcmtk/dcmdata/dcelem.h>

namespace voxray::dicom {

std::optional<DcmTagKey> privateTag(DcmItem* item, Uint16 group, const char* creator,
                                    Uint8 element) {
  if (!item) return std::nullopt;
  for (Uint16 block = 0x10; block <= 0xFF; ++block) {
    OFString s;
    if (item->findAndGetOFString(DcmTagKey(group, block), s).bad()) continue;
    std::string name(s.c_str());
    while (!name.empty() && name.back() == ' ') name.pop_back();
    if (name == creator) return DcmTagKey(group, Uint16(block << 8 | element));
  }
  return std::nullopt;
}

std::string privateText(DcmItem* item, Uint16 group, const char* creator, Uint8 element) {
  constexpr unsigned long kMaxText = 1024;  // private text attributes are short
  const std::optional<DcmTagKey> tag = privateTag(item, group, creator, element);
  DcmElement* e = nullptr;
  if (!tag || item->findAndGetElement(*tag, e).bad() || !e || e->getLength() > kMaxText) return {};
  std::string out;
  OFString s;
  Uint8* bytes = nullptr;
  if (e->getVR() != EVR_UN && e->getOFStringArray(s).good())
    out.assign(s.c_str(), s.length());
  else if (e->getUint8Array(bytes).good() && bytes)
    out.assign(reinterpret_cast<const char*>(bytes), e->getLength());
  while (!out.empty() && (out.back() == ' ' || out.back() == '\0')) out.pop_back();
  return out;
}

}  // namespace voxray::dicom
