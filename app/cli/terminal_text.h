#pragma once
// Text from files and servers as the CLI prints it for a terminal: control characters
// (C0, DEL, C1) and bytes that are not UTF-8 become visible escapes (\x1b, \r, \x00 ...), so
// that a DICOM string or a server's answer cannot clear the screen, set the window title or
// fake an output line. --json needs none of this (JSON escapes them itself).
#include <cstdio>
#include <string>
#include <string_view>

namespace voxray::cli {

inline std::string terminalText(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  auto escape = [&](unsigned char c) {
    static const char* const named[] = {"\\0",   nullptr, nullptr, nullptr, nullptr,
                                        nullptr, nullptr, nullptr, nullptr, "\\t",
                                        "\\n",   nullptr, nullptr, "\\r"};
    if (c < sizeof named / sizeof *named && named[c]) return void(out += named[c]);
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02x", unsigned(c));
    out += hex;
  };
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f) {
      escape(c);
      ++i;
      continue;
    }
    if (c < 0x80) {
      out += char(c);
      ++i;
      continue;
    }
    // A UTF-8 sequence: kept when well formed and not a C1 control (U+0080..U+009F, which
    // some terminals obey as ESC sequences); else its first byte is escaped.
    const size_t n = c >= 0xf0 && c < 0xf5 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 && c < 0xe0 ? 2 : 0;
    bool ok = n > 0 && c < 0xf5 && i + n <= s.size();
    for (size_t k = 1; ok && k < n; ++k) ok = (static_cast<unsigned char>(s[i + k]) & 0xc0) == 0x80;
    if (ok && n == 2 && c == 0xc2 && static_cast<unsigned char>(s[i + 1]) < 0xa0) ok = false;
    if (!ok) {
      escape(c);
      ++i;
      continue;
    }
    out.append(s.substr(i, n));
    i += n;
  }
  return out;
}

}  // namespace voxray::cli
