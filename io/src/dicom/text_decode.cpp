#include "text_decode.h"

#include <dcmtk/dcmdata/dcdeftag.h>
#include <iconv.h>

#include <optional>

namespace voxray::dicom {
namespace {

bool isContinuation(unsigned char c) { return (c & 0xC0) == 0x80; }

// Length of the well-formed UTF-8 sequence at TEXT[i] (RFC 3629: no overlongs, no
// surrogates, nothing above U+10FFFF), or 0.
size_t sequenceLength(const std::string& text, size_t i) {
  const auto at = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = at(i);
  const size_t left = text.size() - i;
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) return left >= 2 && isContinuation(at(i + 1)) ? 2 : 0;
  if (c >= 0xE0 && c <= 0xEF) {
    if (left < 3 || !isContinuation(at(i + 1)) || !isContinuation(at(i + 2))) return 0;
    if (c == 0xE0 && at(i + 1) < 0xA0) return 0;   // overlong
    if (c == 0xED && at(i + 1) >= 0xA0) return 0;  // surrogate
    return 3;
  }
  if (c >= 0xF0 && c <= 0xF4) {
    if (left < 4 || !isContinuation(at(i + 1)) || !isContinuation(at(i + 2)) ||
        !isContinuation(at(i + 3)))
      return 0;
    if (c == 0xF0 && at(i + 1) < 0x90) return 0;   // overlong
    if (c == 0xF4 && at(i + 1) >= 0x90) return 0;  // above U+10FFFF
    return 4;
  }
  return 0;
}

std::optional<std::string> iconvToUtf8(const std::string& raw, const char* from) {
  iconv_t cd = iconv_open("UTF-8", from);
  if (cd == reinterpret_cast<iconv_t>(-1)) return std::nullopt;
  std::string in = raw, out(raw.size() * 4 + 16, '\0');
  char* inPtr = in.data();
  char* outPtr = out.data();
  size_t inLeft = in.size(), outLeft = out.size();
  const size_t result = iconv(cd, &inPtr, &inLeft, &outPtr, &outLeft);
  iconv_close(cd);
  if (result == size_t(-1)) return std::nullopt;
  out.resize(out.size() - outLeft);
  return out;
}

}  // namespace

std::string validUtf8(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    if (size_t n = sequenceLength(text, i)) {
      out.append(text, i, n);
      i += n;
    } else {
      out += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER
      ++i;
    }
  }
  return out;
}

TextDecoder::TextDecoder(DcmItem& dataset) {
  OFString charset;
  dataset.findAndGetOFStringArray(DCM_SpecificCharacterSet, charset);
  // ASCII (none, ISO_IR 6) and UTF-8 (ISO_IR 192) need no conversion, only validation.
  const bool plain = charset.find_first_not_of(" \\") == OFString_npos || charset == "ISO_IR 6" ||
                     charset == "ISO_IR 192";
  convert_ = !plain && converter_.selectCharacterSet(charset).good();
  japanese2022_ = !plain && !convert_ &&
                  (charset.find("ISO 2022 IR 87") != OFString_npos ||
                   charset.find("ISO 2022 IR 159") != OFString_npos);
}

std::string TextDecoder::operator()(const std::string& raw, bool personName) const {
  if (convert_) {
    OFString converted;
    if (converter_
            .convertString(OFString(raw.data(), raw.size()), converted, personName ? "\\^=" : "\\")
            .good())
      return validUtf8(std::string(converted.data(), converted.size()));
  }
  if (japanese2022_) {
    if (auto utf8 = iconvToUtf8(raw, "ISO-2022-JP-2")) return validUtf8(*utf8);
  }
  return validUtf8(raw);
}

}  // namespace voxray::dicom
