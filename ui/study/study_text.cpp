#include "study_text.h"

#include <algorithm>
#include <cctype>

namespace voxray {

namespace {

bool allDigits(const std::string& s) {
  return std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

std::string joined(const std::string& a, const std::string& b, const char* sep = " · ") {
  if (a.empty()) return b;
  return b.empty() ? a : a + sep + b;
}

}  // namespace

std::string displayPersonName(const std::string& dicomName) {
  std::string first = dicomName.substr(0, dicomName.find('='));
  std::vector<std::string> parts;
  size_t start = 0;
  for (;;) {
    size_t caret = first.find('^', start);
    parts.push_back(first.substr(start, caret - start));
    if (caret == std::string::npos) break;
    start = caret + 1;
  }
  std::string given;
  for (size_t i = 1; i < parts.size() && i < 3; ++i) given = joined(given, parts[i], " ");
  return joined(parts[0], given, ", ");
}

std::string displayDate(const std::string& da, const std::string& tm) {
  if (da.size() != 8 || !allDigits(da)) return da;
  std::string out = da.substr(0, 4) + "-" + da.substr(4, 2) + "-" + da.substr(6, 2);
  if (tm.size() >= 4 && allDigits(tm.substr(0, 4)))
    out += " " + tm.substr(0, 2) + ":" + tm.substr(2, 2);
  return out;
}

std::vector<std::string> studyTextLines(const StudyIdentity& s) {
  std::vector<std::string> lines;
  auto add = [&lines](const std::string& line) {
    if (!line.empty()) lines.push_back(line);
  };
  add(displayPersonName(s.patientName));
  std::string id = s.patientId.empty() ? "" : "ID " + s.patientId;
  std::string born = s.patientBirthDate.empty() ? "" : "born " + displayDate(s.patientBirthDate);
  add(joined(id, born));
  add(joined(displayDate(s.studyDate, s.studyTime), s.studyDescription));
  add(s.accessionNumber.empty() ? "" : "Acc " + s.accessionNumber);
  std::string series = s.seriesNumber > 0 ? "Series " + std::to_string(s.seriesNumber) : "";
  add(joined(series, s.seriesDescription));
  return lines;
}

}  // namespace voxray
