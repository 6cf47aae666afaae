#include "raw_preview.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <vector>

#include "voxray/io/orientation.h"

namespace fs = std::filesystem;

namespace voxray::ui {

namespace {

// Slice files of a folder in the order of the number at the end of their names.
std::vector<fs::path> sliceFiles(const fs::path& dir) {
  std::vector<std::pair<long, fs::path>> numbered;
  std::error_code ec;
  static const std::regex trailing("([0-9]+)[^0-9]*$");
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (!e.is_regular_file()) continue;
    std::smatch m;
    std::string name = e.path().filename().string();
    long n = std::regex_search(name, m, trailing) ? std::stol(m[1]) : 0;
    numbered.emplace_back(n, e.path());
  }
  std::sort(numbered.begin(), numbered.end());
  std::vector<fs::path> out;
  for (auto& [n, p] : numbered) out.push_back(p);
  return out;
}

double sampleAt(const uint8_t* p, const RawLayout& l) {
  int n = int(sampleBytes(l.type));
  uint8_t b[4];
  std::memcpy(b, p, size_t(n));
  bool swap = (l.order == ByteOrder::Big) != (std::endian::native == std::endian::big);
  if (swap) std::reverse(b, b + n);
  switch (l.type) {
    case SampleType::U8:
      return b[0];
    case SampleType::I16: {
      int16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case SampleType::U16: {
      uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case SampleType::F32: {
      float v;
      std::memcpy(&v, b, 4);
      return v;
    }
  }
  return 0;
}

}  // namespace

RawSizeCheck checkRawSize(const std::string& path, const RawLayout& l) {
  RawSizeCheck c;
  std::error_code ec;
  c.sliceBytes = uint64_t(std::max(l.dims.x, 0)) * uint64_t(std::max(l.dims.y, 0)) *
                 uint64_t(sampleBytes(l.type));
  if (fs::is_directory(path, ec)) {
    auto files = sliceFiles(path);
    c.files = int(files.size());
    c.filesWanted = std::max(l.dims.z, 0);
    c.expectedBytes = c.sliceBytes + l.headerBytes;
    if (!files.empty()) c.actualBytes = fs::file_size(files.front(), ec);
  } else if (fs::is_regular_file(path, ec)) {
    c.files = 1;
    c.actualBytes = fs::file_size(path, ec);
    uint64_t slices = uint64_t(std::max(l.dims.z, 0));
    if (slices == 0) {  // as many whole slices as the file holds, at least one
      uint64_t data = c.actualBytes > l.headerBytes ? c.actualBytes - l.headerBytes : 0;
      slices = std::max<uint64_t>(c.sliceBytes ? data / c.sliceBytes : 0, 1);
    }
    c.expectedBytes = c.sliceBytes * slices + l.headerBytes;
  }
  return c;
}

std::string sizeMismatchText(const RawSizeCheck& c) {
  if (c.files == 0 || c.matches()) return {};
  if (c.filesWanted != 0 && c.filesWanted != c.files) {
    int off = c.files - c.filesWanted;
    return "the folder has " + std::to_string(c.files) + " slice files, the layout " +
           std::to_string(c.filesWanted) + " (" + std::to_string(std::abs(off)) + " file(s) " +
           (off > 0 ? "too many" : "missing") + ")";
  }
  const bool longer = c.actualBytes > c.expectedBytes;
  const uint64_t off = longer ? c.actualBytes - c.expectedBytes : c.expectedBytes - c.actualBytes;
  std::string text = (c.files > 1 ? "the first file is " : "the file is ") + std::to_string(off) +
                     " bytes too " + (longer ? "long" : "short");
  if (c.files == 1 && c.sliceBytes > 0) {  // a folder's files hold one slice each
    char slices[32];
    double n = double(off) / double(c.sliceBytes);
    std::snprintf(slices, sizeof slices, n == std::floor(n) ? "%.0f" : "%.2f", n);
    text += std::string(" (") + slices + " slices)";
  }
  return text;
}

std::optional<RawPreview> previewRawSlice(const std::string& path, const RawLayout& l) {
  if (l.dims.x <= 0 || l.dims.y <= 0) return std::nullopt;
  size_t sliceBytes = size_t(l.dims.x) * size_t(l.dims.y) * size_t(sampleBytes(l.type));
  fs::path file = path;
  size_t offset = l.headerBytes;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    auto files = sliceFiles(path);
    if (files.empty()) return std::nullopt;
    file = files[files.size() / 2];
  } else {
    offset += sliceBytes * size_t(std::max(l.dims.z, 1) / 2);
  }
  std::ifstream in(file, std::ios::binary);
  std::vector<uint8_t> bytes(sliceBytes);
  in.seekg(std::streamoff(offset));
  if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(sliceBytes)))
    return std::nullopt;
  std::vector<double> values(size_t(l.dims.x) * size_t(l.dims.y));
  for (size_t i = 0; i < values.size(); ++i)
    values[i] = sampleAt(&bytes[i * size_t(sampleBytes(l.type))], l);
  auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  double range = std::max(*hi - *lo, 1e-9);
  RawPreview out{Image(l.dims.x, l.dims.y), *lo, *hi};
  for (size_t i = 0; i < values.size(); ++i) {
    uint8_t g = uint8_t(255.0 * (values[i] - *lo) / range);
    uint8_t* p = &out.image.rgba[i * 4];
    p[0] = p[1] = p[2] = g;
    p[3] = 255;
  }
  return out;
}

std::string valueRangeText(const RawPreview& p, const RawLayout& l) {
  double a = p.lo * l.slope + l.intercept, b = p.hi * l.slope + l.intercept;
  char text[160];
  std::snprintf(text, sizeof text, "middle slice: %g … %g", std::min(a, b), std::max(a, b));
  std::string out = text;
  // CT in HU has air at about -1000; a slice whose lowest value is far above is not in HU.
  constexpr double kAirAtMostHu = -500.0;
  if (std::min(a, b) > kAirAtMostHu)
    out += " — not HU? CT air is about −1000: set the rescale (e.g. 1, −1024)";
  return out;
}

EdgeLetters edgeLetters(const glm::dmat3& direction) {
  static const std::string letters = "LRAPSI";  // each letter beside its opposite
  auto opposite = [](char c) {
    size_t i = letters.find(c);
    return letters[i ^ 1U];
  };
  std::string code = axesCodeFromDirection(direction);
  EdgeLetters e;
  e.right = code[0];
  e.left = opposite(code[0]);
  e.bottom = code[1];
  e.top = opposite(code[1]);
  e.slices = code[2];
  return e;
}

}  // namespace voxray::ui
