#include "nrrd_header_check.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "sample_grid.h"
#include "voxray/io/error.h"

namespace fs = std::filesystem;

namespace voxray::formats {
namespace {

// The file's first kMaxNrrdHeaderBytes + 1 bytes split into lines at "\n" or "\r\n"; WHOLE:
// the file ended within them. A lone "\r" stays in its line, where checkText refuses it
// (Teem's reader may end a line there: the two would see different fields).
struct Text {
  std::vector<std::string> lines;
  bool whole = false;
};

Text readLines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(kMaxNrrdHeaderBytes + 1, '\0');
  in.read(bytes.data(), std::streamsize(bytes.size()));
  bytes.resize(size_t(in.gcount()));
  Text t;
  t.whole = bytes.size() <= kMaxNrrdHeaderBytes;
  size_t start = 0;
  for (size_t end; (end = bytes.find('\n', start)) != std::string::npos; start = end + 1)
    t.lines.push_back(bytes.substr(start, end - start - (end > start && bytes[end - 1] == '\r')));
  if (start < bytes.size()) t.lines.push_back(bytes.substr(start));
  return t;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// A field line or a listed file's name no longer than Teem can quote in a message.
void checkFieldLength(const std::string& line, size_t number, const std::string& path) {
  if (line.size() > kMaxNrrdFieldLineBytes)
    throw inputError(path + ": header line " + std::to_string(number) + " is " +
                     std::to_string(line.size()) +
                     " characters long; Voxray reads fields of up to " +
                     std::to_string(kMaxNrrdFieldLineBytes) + " (the header is damaged)");
}

// A header line is text: a control byte would end the line early for Teem (NUL) or for us.
void checkText(const std::string& line, size_t number, const std::string& path) {
  for (const char c : line) {
    const auto b = static_cast<unsigned char>(c);
    if (b < 0x20 && c != '\t') {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", b);
      throw inputError(path + ": header line " + std::to_string(number) + " holds the byte " + hex +
                       ", which is not text; the header is damaged");
    }
  }
}

bool readInt(const std::string& word, long limit, long& out) {
  const char* end = word.data() + word.size();
  auto [ptr, ec] = std::from_chars(word.data(), end, out);
  return ec == std::errc() && ptr == end && out >= -limit && out <= limit;
}

// The product of the "sizes" field's numbers (saturating); 0 when there is none readable.
uint64_t sampleCount(const std::string& value) {
  std::istringstream in(value);
  uint64_t product = 1, size = 0;
  bool any = false;
  while (in >> size) {
    any = true;
    product = size != 0 && product > UINT64_MAX / size ? UINT64_MAX : product * size;
  }
  return any ? product : 0;
}

void checkFileCount(uint64_t count, uint64_t samples, const std::string& path) {
  const uint64_t most =
      samples ? std::min<uint64_t>(kMaxNrrdDataFiles, samples) : kMaxNrrdDataFiles;
  if (count > most)
    throw inputError(path + ": the header names " + std::to_string(count) +
                     " data files; at most " + std::to_string(most) +
                     " are read (one per slice at most, and no more than " +
                     std::to_string(kMaxNrrdDataFiles) + "); the header is damaged");
}

// "NAME%03d.raw FIRST LAST STEP [DIM]". Teem prints NAME with each number into a buffer 10
// characters longer than NAME: one integer conversion of at most 12 digits' width and numbers
// of at most 9 digits fit it, and keep Teem's own count of the range (an int) from overflowing.
void readPattern(const std::string& value, uint64_t samples, NrrdDataFiles& d,
                 const std::string& path) {
  std::istringstream in(value);
  std::string word;
  std::vector<std::string> words;
  in >> d.format;
  while (in >> word) words.push_back(word);
  static const std::regex oneInteger("[^%]*%0?([0-9]{0,2})d[^%]*");
  std::smatch m;
  long first = 0, last = 0, step = 0, dim = 1;
  constexpr long kLargest = 999999999;
  const bool ok = std::regex_match(d.format, m, oneInteger) &&
                  (m[1].length() == 0 || std::stoi(m[1].str()) <= 12) &&
                  (words.size() == 3 || words.size() == 4) && readInt(words[0], kLargest, first) &&
                  readInt(words[1], kLargest, last) && readInt(words[2], kLargest, step) &&
                  step != 0 && (last - first) * step >= 0 &&
                  (words.size() == 3 || (readInt(words[3], 16, dim) && dim >= 1));
  if (!ok)
    throw inputError(path + ": its data file pattern '" + value +
                     "' is not one Voxray reads (NAME%03d.raw FIRST LAST STEP: one %d at most 12 "
                     "digits wide, numbers of at most 9 digits, a step from FIRST to LAST); "
                     "the header is damaged");
  checkFileCount(uint64_t((last - first) / step) + 1, samples, path);
  d.first = int(first), d.last = int(last), d.step = int(step);
  std::vector<char> buffer(d.format.size() + 32);
  for (long k = first; step > 0 ? k <= last : k >= last; k += step) {
    std::snprintf(buffer.data(), buffer.size(), d.format.c_str(), int(k));
    d.files.push_back({buffer.data(), ""});
  }
}

// Resolves each data file as Teem opens it: names starting with "/" (or "X:") as given, others
// in the header's folder. Each must be a regular file in that folder once links are resolved.
void placeFiles(NrrdDataFiles& d, const fs::path& folder, const std::string& path) {
  for (auto& f : d.files) {
    const std::string& name = f.name;
    if (name == "-")
      throw inputError(path + ": its data file is '-' (standard input); Voxray reads data " +
                       "files beside the header");
    const std::string& lead = d.format.empty() ? name : d.format;  // what Teem looks at
    const bool asGiven = !lead.empty() && (lead[0] == '/' || (lead.size() > 1 && lead[1] == ':'));
    const std::string candidate = asGiven ? name : (folder / name).string();
    f.resolved = dataFileInFolder(path, name, candidate);
  }
}

}  // namespace

NrrdDataFiles checkNrrdHeader(const std::string& path) {
  const Text text = readLines(path);
  NrrdDataFiles d;
  uint64_t samples = 0;
  bool ended = false;
  std::set<std::string> seen;  // field names without spaces ("data file" is "datafile" too)
  size_t fields = 0;
  std::string listed;  // "LIST" or "SKIPLIST": the lines after the field name the files
  size_t n = 1;        // line 1 is the magic, checked before
  for (; n < text.lines.size() && listed.empty(); ++n) {
    const std::string& line = text.lines[n];
    if (line.empty()) {
      ended = true;
      break;
    }
    if (++fields > kMaxNrrdHeaderLines)
      throw inputError(path + ": the header has more than " + std::to_string(kMaxNrrdHeaderLines) +
                       " lines; Voxray reads headers of up to " +
                       std::to_string(kMaxNrrdHeaderLines) + " lines (the file is damaged)");
    checkText(line, n + 1, path);
    const size_t colon = line.find(':');
    const bool keyValue =
        colon != std::string::npos && colon + 1 < line.size() && line[colon + 1] == '=';
    if (line[0] == '#' || keyValue) continue;  // comments and key/value pairs
    checkFieldLength(line, n + 1, path);
    if (colon == std::string::npos || colon + 1 == line.size())
      continue;  // lines Teem refuses itself
    std::string field = lower(line.substr(0, colon));
    field.erase(0, field.find_first_not_of(" \t"));
    field.erase(field.find_last_not_of(" \t") + 1);
    const size_t at = line.find_first_not_of(" \t", colon + 1);
    const std::string value = at == std::string::npos ? "" : line.substr(at);
    // Teem leaks what it parsed of a field given again (LeakSanitizer, the volume_file fuzz
    // target): a real header gives each field once.
    std::string name = field;
    name.erase(std::remove(name.begin(), name.end(), ' '), name.end());
    if (!seen.insert(name).second)
      throw inputError(path + ": the header gives the field '" + field + "' twice; it is damaged");
    if (field == "sizes") samples = sampleCount(value);
    if (field != "data file" && field != "datafile") continue;
    // Teem reads the data file field against the dimension and sizes given before it, and
    // leaks its file list when they are not there (LeakSanitizer, the volume_file target).
    if (!seen.count("dimension") || !seen.count("sizes"))
      throw inputError(path + ": its data file field comes before the dimension and sizes; the " +
                       "header is damaged");
    if (value.find('%') != std::string::npos) {
      readPattern(value, samples, d, path);
    } else if (value.rfind("LIST", 0) == 0 || value.rfind("SKIPLIST", 0) == 0) {
      listed = value.substr(0, value.find("LIST") + 4);
    } else {
      d.names.push_back(value);
      d.files.push_back({value, ""});
    }
  }
  if (!listed.empty()) {
    for (; n < text.lines.size(); ++n) {
      checkText(text.lines[n], n + 1, path);
      checkFieldLength(text.lines[n], n + 1, path);
      checkFileCount(d.names.size() + 1, samples, path);
      std::string name = text.lines[n];
      if (listed == "SKIPLIST") {  // "BYTES NAME"
        const size_t gap = name.find_first_of(" \t"), at = name.find_first_not_of(" \t", gap);
        name = at == std::string::npos ? "" : name.substr(at);
      }
      d.names.push_back(name);
      d.files.push_back({name, ""});
    }
    if (d.names.empty())
      throw inputError(path + ": its data file " + listed +
                       " names no file; the header is damaged");
    ended = true;
  }
  if (!ended && !text.whole)
    throw inputError(path + ": the header is longer than " +
                     std::to_string(kMaxNrrdHeaderBytes >> 20) +
                     " MiB or does not end (no empty line after it); the file is damaged");
  placeFiles(d, fs::absolute(path).parent_path(), path);
  return d;
}

void checkNrrdDataFileSizes(const NrrdDataFiles& d, uint64_t bytesPerFile, bool skips,
                            const std::string& path) {
  for (const auto& f : d.files) {
    std::error_code ec;
    const uint64_t size = fs::file_size(f.resolved, ec);
    if (!ec && (skips ? size >= bytesPerFile : size == bytesPerFile)) continue;
    throw inputError(path + ": its data file '" + f.name + "' holds " + std::to_string(size) +
                     " bytes where the header's sizes and type need " + (skips ? "at least " : "") +
                     std::to_string(bytesPerFile) +
                     "; the data file does not belong to this header, or one of them is damaged");
  }
}

}  // namespace voxray::formats
