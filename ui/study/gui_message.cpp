#include "gui_message.h"

#include <algorithm>
#include <cctype>
#include <utility>
#include <vector>

#include "voxray/io/error.h"

namespace voxray {

namespace {

// Input flag key -> the workstation's name for it. Flags with no field of their own (the
// slice range, the series) get words for what the workstation offers instead.
const std::vector<std::pair<std::string, std::string>>& fields() {
  static const std::vector<std::pair<std::string, std::string>> table = {
      {"raw-dims", "Dimensions x, y, z"},
      {"raw-type", "Sample type"},
      {"raw-endian", "Byte order"},
      {"raw-offset", "Header offset"},
      {"raw-spacing", "Spacing x, y, z"},
      {"raw-rescale", "Rescale slope, intercept"},
      {"raw-axes", "Orientation (x, y, z)"},
      {"raw-range", "Slice range"},
      {"series", "the series picker (File \u2192 Open DICOM folder\u2026)"},
      {"time", "the time point of a 4D series"},
  };
  return table;
}

bool isHintChar(char c) {
  return std::isupper(static_cast<unsigned char>(c)) ||
         std::isdigit(static_cast<unsigned char>(c)) || c == ',' || c == '-' || c == '[' ||
         c == ']';
}

}  // namespace

const std::string& inputFieldLabel(const std::string& key) {
  const auto& table = fields();
  auto it = std::find_if(table.begin(), table.end(), [&](const auto& f) { return f.first == key; });
  if (it == table.end()) throw inputError("no workstation field for the input flag --" + key);
  return it->second;
}

std::string guiMessage(const std::string& message) {
  std::string out;
  size_t i = 0;
  while (i < message.size()) {
    size_t at = message.find("--", i);
    if (at == std::string::npos) break;
    size_t end = at + 2;
    while (end < message.size() &&
           (std::islower(static_cast<unsigned char>(message[end])) || message[end] == '-'))
      ++end;
    const std::string key = message.substr(at + 2, end - at - 2);
    const auto& table = fields();
    auto it =
        std::find_if(table.begin(), table.end(), [&](const auto& f) { return f.first == key; });
    if (it == table.end()) {  // not an input flag: kept as written
      out += message.substr(i, end - i);
      i = end;
      continue;
    }
    // A value hint after the flag ("X,Y,Z", "FIRST-LAST") names the CLI's syntax: dropped.
    size_t hint = end;
    if (hint + 1 < message.size() && message[hint] == ' ' && isHintChar(message[hint + 1]) &&
        std::isupper(static_cast<unsigned char>(message[hint + 1]))) {
      hint += 1;
      while (hint < message.size() && isHintChar(message[hint])) ++hint;
      end = hint;
    }
    out += message.substr(i, at - i) + "\u201c" + it->second + "\u201d";
    i = end;
  }
  return out + message.substr(std::min(i, message.size()));
}

}  // namespace voxray
