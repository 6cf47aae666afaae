#include "metaimage_read.h"

#include <metaImage.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <set>
#include <sstream>

#include "voxray/io/error.h"

namespace voxray::formats {
namespace {

constexpr KindCodes kMetaTypes = {MET_UCHAR, MET_CHAR, MET_USHORT, MET_SHORT,
                                  MET_UINT,  MET_INT,  MET_FLOAT,  MET_DOUBLE};

// The acronym MetaIO writers derive from the directions (ITK's convention: the side each axis
// comes from, "RAI" for L, P, S), to compare with the file's AnatomicalOrientation.
std::string orientationAcronym(const glm::dmat3& direction) {
  std::string code;
  for (int a = 0; a < 3; ++a) {
    const glm::dvec3 d = direction[a];
    const int c = std::abs(d.x) >= std::abs(d.y) && std::abs(d.x) >= std::abs(d.z) ? 0
                  : std::abs(d.y) >= std::abs(d.z)                                 ? 1
                                                                                   : 2;
    static const char from[3][2] = {{'R', 'L'}, {'A', 'P'}, {'I', 'S'}};
    code += from[c][d[c] < 0 ? 1 : 0];
  }
  return code;
}

void checkAnatomicalOrientation(SampleGrid& g, const MetaImage& image) {
  const char* given = image.AnatomicalOrientationAcronym();
  const std::string file = given ? given : "";
  if (file.size() < 3 || file.find('?') != std::string::npos) return;
  const std::string matrix = orientationAcronym(g.direction);
  if (file.substr(0, 3) != matrix)
    g.warnings.push_back("the header's AnatomicalOrientation (" + file.substr(0, 3) +
                         ") disagrees with its TransformMatrix (" + matrix +
                         "); the TransformMatrix is used, as ITK and 3D Slicer do");
}

// NAME (a detached data file) where MetaIO opens it: relative names in the header's folder,
// full paths as given. It must be a regular file in the header's folder (dataFileInFolder).
void checkInFolder(const std::string& path, const std::string& name) {
  const std::filesystem::path file(name);
  dataFileInFolder(
      path, name,
      file.is_absolute() ? name : (std::filesystem::absolute(path).parent_path() / file).string());
}

// The bytes NEEDED for the samples cannot come from a header file and a single data file
// that hold less (or, compressed, less than 1/1032 of it, deflate's largest ratio): refused
// before the samples' buffer is allocated (a few header bytes claimed 9 GiB; libFuzzer). Lists
// and patterns of files are checked file by file as MetaIO reads them.
void checkDataSize(const std::string& path, const MetaImage& image, uint64_t needed) {
  const std::string data = image.ElementDataFileName();
  const bool local = data.empty() || data == "LOCAL" || data == "Local" || data == "local";
  if (!local && (data.rfind("LIST", 0) == 0 || data.find(' ') != std::string::npos)) return;
  const std::filesystem::path file = local ? std::filesystem::path(path)
                                     : std::filesystem::path(data).is_absolute()
                                         ? std::filesystem::path(data)
                                         : std::filesystem::absolute(path).parent_path() / data;
  std::error_code ec;
  const uint64_t held = std::filesystem::file_size(file, ec);
  if (ec) return;  // MetaIO's own read reports it
  const uint64_t most = image.CompressedData() ? held * 1032 : held;
  if (needed > most)
    throw inputError(path + ": its header's sizes need " + std::to_string(needed) +
                     " bytes of samples, more than " + (local ? "the file" : "its data file") +
                     " holds (" + std::to_string(held) + " bytes" +
                     (image.CompressedData() ? ", compressed" : "") +
                     "); the file is damaged or truncated");
}

// "NAME%03d.raw MIN MAX STEP": MetaIO formats NAME with the file's own text as a printf
// format, so only one integer conversion is allowed, and every file must exist.
void checkPattern(const std::string& path, const std::string& data) {
  std::istringstream in(data);
  std::string pattern;
  long first = 0, last = 0, step = 1;
  in >> pattern >> first >> last;
  if (!(in >> step)) step = 1;
  const std::regex oneInteger("[^%]*%0?[0-9]{0,2}d[^%]*");
  if (!in.eof() || !std::regex_match(pattern, oneInteger) || step < 1 || last < first ||
      (last - first) / step > 100000)
    throw inputError(path + ": its ElementDataFile '" + data +
                     "' is not a slice pattern Voxray reads (NAME%03d.raw FIRST LAST STEP)");
  char name[4096];
  for (long k = first; k <= last; k += step) {
    std::snprintf(name, sizeof name, pattern.c_str(), int(k));
    checkInFolder(path, name);
  }
}

// "LIST": the slice files are named on the header's following lines, one per line.
void checkList(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  bool listed = false;
  while (std::getline(in, line)) {
    if (!listed) {
      listed = line.rfind("ElementDataFile", 0) == 0;
      continue;
    }
    const size_t a = line.find_first_not_of(" \t\r"), b = line.find_last_not_of(" \t\r");
    if (a != std::string::npos) checkInFolder(path, line.substr(a, b - a + 1));
  }
}

// A detached data file that is not there: said plainly before MetaIO tries it (MetaIO's own
// failure there is vague and leaks the stream it opened, for single files, patterns and lists
// alike; libFuzzer's leak check found the pattern case). One outside the header's folder, or
// no regular file, is not read either (issue 39: /etc/passwd as voxels).
void checkDataFile(const std::string& path, const MetaImage& image) {
  const std::string data = image.ElementDataFileName();
  if (data.empty() || data == "LOCAL" || data == "Local" || data == "local") return;
  if (data.rfind("LIST", 0) == 0) {
    // MetaIO takes the listed files' dimension from the word after LIST (through atof, so any
    // word reads as some number) or NDims - 1, and crashes on some (libFuzzer: a SEGV in
    // ReadStream); only "LIST" and "LIST nD" for slices or volumes are read.
    static const std::regex form(R"(LIST(?:[ \t]+([0-9]{1,2})D)?[ \t]*)");
    std::smatch m;
    if (!std::regex_match(data, m, form))
      throw inputError(path + ": its ElementDataFile '" + data +
                       "' is not a file list Voxray reads (LIST, or LIST 2D)");
    const int dim = m[1].matched ? std::stoi(m[1].str()) : image.NDims() - 1;
    if (dim < 2 || dim > image.NDims())
      throw inputError(path + ": its files hold " + std::to_string(dim) + "D images of a " +
                       std::to_string(image.NDims()) +
                       "D image; Voxray reads lists of 2D slices (LIST 2D)");
    return checkList(path);
  }
  if (data.find(' ') != std::string::npos) return checkPattern(path, data);
  checkInFolder(path, data);
}

// MetaIO copies each header field's name into a 255-byte array with strcpy (an abort under
// _FORTIFY_SOURCE, heap corruption otherwise; libFuzzer found both), so a name longer than any
// real one is refused first. MetaIO reads a name up to '=', ':' or a line end, and a line
// without a separator makes it skip to the next '=' on a later line, past where a check of
// lines would stop; so every header line up to the ElementDataFile field (where MetaIO stops
// and data may follow) must be blank or "Name = value" with a short name. The header is text:
// a byte that is not, a name that is not a word, or a field given twice is damage that MetaIO
// would read on into (libFuzzer found heap corruption behind such headers too).
void checkHeaderLines(const std::string& path) {
  constexpr size_t kLongestLine = 250, kLongestHeader = 64 * 1024;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::set<std::string> seen;
  size_t read = 0;
  for (int n = 1; std::getline(in, line); ++n) {
    const std::string where = path + ": header line " + std::to_string(n);
    if (line.size() > kLongestLine)
      throw inputError(where + " is " + std::to_string(line.size()) + " characters long (at most " +
                       std::to_string(kLongestLine) + " are read); the file is damaged");
    read += line.size() + 1;
    for (const char c : line) {
      const auto b = static_cast<unsigned char>(c);
      if ((b < 0x20 || b > 0x7e) && c != '\t' && c != '\r') {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02x", b);
        throw inputError(where + " holds the byte " + hex +
                         ", which is not text; the header is damaged");
      }
    }
    const size_t first = line.find_first_not_of(" \t\r\v\f");
    if (first == std::string::npos) continue;
    const size_t sep = line.find_first_of("=:\r", first);
    if (sep == std::string::npos || line[sep] == '\r')
      throw inputError(where + " is not a 'Name = value' field; the file is damaged");
    const size_t last = line.find_last_not_of(" \t\v\f", sep - 1);
    const std::string name =
        last == std::string::npos || last < first ? "" : line.substr(first, last - first + 1);
    const bool word = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
    if (!word) throw inputError(where + " is not a 'Name = value' field; the file is damaged");
    if (!seen.insert(name).second)
      throw inputError(where + " gives the field " + name + " a second time; the file is damaged");
    // MetaIO reads NDims numbers for each array field: a huge NDims reads (hangs) for ever.
    if (name == "NDims") {
      const std::string value = line.substr(sep + 1);
      const long dims = std::strtol(value.c_str(), nullptr, 10);
      if (dims < 2 || dims > 10)
        throw inputError(path + ": NDims is '" + value + "'; Voxray opens 2 to 10 dimensions");
    }
    if (name == "ElementDataFile") return;
    if (read > kLongestHeader) break;
  }
  throw inputError(path + ": no ElementDataFile field in its header (within the first " +
                   std::to_string(kLongestHeader / 1024) +
                   " KiB); not a MetaImage file, or a damaged one");
}

}  // namespace

SampleGrid readMetaImage(const std::string& path) {
  checkHeaderLines(path);
  MetaImage image;
  if (!image.Read(path.c_str(), false))
    throw inputError(path + ": not a readable MetaImage file (its header is missing or damaged)");
  const int n = image.NDims();
  if (n < 2 || n > 10)
    throw inputError(path + ": holds a " + std::to_string(n) + "D image; Voxray opens volumes");
  SampleGrid g;
  uint64_t extra = uint64_t(std::max(image.ElementNumberOfChannels(), 1));
  glm::dmat3 steps(0.0);
  for (int a = 0; a < n; ++a) {
    if (image.DimSize(a) < 1)
      throw inputError(path + ": the header gives a dimension of size " +
                       std::to_string(image.DimSize(a)) + "; the file is damaged");
    if (a >= 3) {
      extra *= uint64_t(image.DimSize(a));
      continue;
    }
    g.dims[size_t(a)] = uint64_t(image.DimSize(a));
    for (int r = 0; r < 3 && r < n; ++r)
      steps[a][r] = image.TransformMatrix(a, r) * image.ElementSpacing(a);
    g.originMm[a] = image.Position(a);
  }
  if (n == 2) {
    g.dims[2] = 1;
    steps[2] = glm::cross(steps[0], steps[1]);
    steps[2] /= glm::length(steps[2]);  // one slice: thickness 1 mm along the normal
  }
  checkDims(g.dims, extra, path);
  setAxes(g, steps, path);
  if (!std::isfinite(g.originMm.x + g.originMm.y + g.originMm.z))
    throw inputError(path + ": the origin in the header is not a number; the file is damaged");
  checkAnatomicalOrientation(g, image);
  g.decoding.kind = kindOfCode(kMetaTypes, image.ElementType(),
                               "MetaImage type " + std::to_string(int(image.ElementType())), path);
  g.sourceType = kindName(g.decoding.kind);
  checkDataFile(path, image);

  const size_t channels = size_t(std::max(image.ElementNumberOfChannels(), 1));
  const size_t s = detail::sampleBytes(g.decoding.kind);
  const size_t count = g.dims[0] * g.dims[1] * g.dims[2];
  checkDataSize(path, image, uint64_t(count) * s * extra);
  auto buffer = std::shared_ptr<uint8_t[]>(new uint8_t[count * s * extra]);
  MetaImage full;
  if (!full.Read(path.c_str(), true, buffer.get()))
    throw inputError(path + ": the data cannot be read; the file or its data file is damaged, " +
                     "truncated or missing");
  if (channels > 1) {  // keep channel 0 of each voxel, packed in place
    for (size_t i = 1; i < count; ++i)
      std::memmove(buffer.get() + i * s, buffer.get() + i * channels * s, s);
    g.warnings.push_back("each voxel holds " + std::to_string(channels) +
                         " values (a vector or list axis); the first is shown");
  }
  if (extra / channels > 1)
    g.warnings.push_back("the file holds " + std::to_string(extra / channels) +
                         " volumes (4D: time points, phases or diffusion directions); this is " +
                         "volume 1 of " + std::to_string(extra / channels));
  g.samples = buffer.get();
  g.storage = std::move(buffer);
  return g;
}

}  // namespace voxray::formats
