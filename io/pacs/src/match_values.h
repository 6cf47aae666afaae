#pragma once
// Counts in a search answer (NumberOfStudyRelatedSeries ...) as both transports read them:
// only a whole number in 0..INT_MAX counts; anything else (1.5e300, 2.5, "12abc") is 0, which
// PacsMatch reads as "the node did not say".
#include <charconv>
#include <climits>
#include <string>

namespace voxray::pacs {

inline int countValue(const std::string& text) {
  size_t b = text.find_first_not_of(' '), e = text.find_last_not_of(' ');
  if (b == std::string::npos) return 0;
  if (text[b] == '+') ++b;
  long long v = 0;
  const char* last = text.data() + e + 1;
  auto [end, ec] = std::from_chars(text.data() + b, last, v);
  return ec == std::errc() && end == last && v >= 0 && v <= INT_MAX ? int(v) : 0;
}

}  // namespace voxray::pacs
