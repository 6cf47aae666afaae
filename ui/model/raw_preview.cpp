#include "raw_preview.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <vector>

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
  uint64_t slice = uint64_t(std::max(l.dims.x, 0)) * uint64_t(std::max(l.dims.y, 0)) *
                   uint64_t(sampleBytes(l.type));
  if (fs::is_directory(path, ec)) {
    auto files = sliceFiles(path);
    c.files = int(files.size());
    c.expectedBytes = slice + l.headerBytes;
    if (!files.empty()) c.actualBytes = fs::file_size(files.front(), ec);
  } else if (fs::is_regular_file(path, ec)) {
    c.files = 1;
    c.expectedBytes = slice * uint64_t(std::max(l.dims.z, 1)) + l.headerBytes;
    c.actualBytes = fs::file_size(path, ec);
  }
  return c;
}

std::optional<Image> previewRawSlice(const std::string& path, const RawLayout& l) {
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
  Image img(l.dims.x, l.dims.y);
  for (size_t i = 0; i < values.size(); ++i) {
    uint8_t g = uint8_t(255.0 * (values[i] - *lo) / range);
    uint8_t* p = &img.rgba[i * 4];
    p[0] = p[1] = p[2] = g;
    p[3] = 255;
  }
  return img;
}

}  // namespace voxray::ui
