#include "voxray/io/raw_check.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "raw_samples.h"
#include "raw_size_rule.h"
#include "raw_slice_files.h"
#include "voxray/io/error.h"

namespace fs = std::filesystem;

namespace voxray {

namespace detail {

RawFileBytes rawFileBytes(const RawLayout& l, uint64_t found, bool stackSlice) {
  RawFileBytes r;
  r.sliceBytes = uint64_t(std::max(l.dims.x, 0)) * uint64_t(std::max(l.dims.y, 0)) *
                 uint64_t(sampleBytes(l.type));
  if (stackSlice) {
    r.slices = 1;
  } else if (l.dims.z > 0) {
    r.slices = uint64_t(l.dims.z);
  } else {
    const uint64_t data = found > l.headerBytes ? found - l.headerBytes : 0;
    r.slices = r.sliceBytes ? data / r.sliceBytes : 0;
    r.partialSlice = data == 0 || r.slices * r.sliceBytes != data;
    r.slices = std::max<uint64_t>(r.slices, 1);
  }
  r.expected = l.headerBytes + r.slices * r.sliceBytes;
  return r;
}

}  // namespace detail

namespace {

uint64_t sizeOf(const std::string& path) {
  std::error_code ec;
  const auto n = fs::file_size(path, ec);
  return ec ? 0 : uint64_t(n);
}

// A pattern such as slices/%03d.tif: not a file itself, but it names some.
bool isPattern(const std::string& input) {
  std::error_code ec;
  return input.find('%') != std::string::npos && !fs::exists(input, ec);
}

// The slice files of a folder or a pattern (the importer's own rules), in slice order.
std::vector<detail::SliceFile> stackFiles(const std::string& input, const RawLayout& l) {
  std::error_code ec;
  return fs::is_directory(input, ec) ? detail::listSliceFolder(input, l.range)
                                     : detail::listSlicePattern(input, l.range);
}

}  // namespace

RawSizeCheck checkRawSize(const std::string& input, const RawLayout& l) {
  RawSizeCheck c;
  std::error_code ec;
  try {
    if (fs::is_directory(input, ec) || isPattern(input)) {
      auto files = stackFiles(input, l);
      c.files = int(files.size());
      c.filesWanted = std::max(l.dims.z, 0);
      for (const auto& f : files) {  // the first file whose size is off decides
        const uint64_t found = sizeOf(f.path);
        const auto rule = detail::rawFileBytes(l, found, true);
        c.sliceBytes = rule.sliceBytes;
        c.expectedBytes = rule.expected;
        c.actualBytes = found;
        c.file = fs::path(f.path).filename().string();
        if (found != rule.expected) break;
      }
    } else if (fs::is_regular_file(input, ec)) {
      c.files = 1;
      c.file = fs::path(input).filename().string();
      c.actualBytes = sizeOf(input);
      const auto rule = detail::rawFileBytes(l, c.actualBytes, false);
      c.sliceBytes = rule.sliceBytes;
      c.expectedBytes = rule.expected;
    } else {
      c.problem = "no such file or folder";
    }
  } catch (const Error& e) {
    c = RawSizeCheck{};
    c.problem = e.what();
  }
  return c;
}

std::string sizeMismatchText(const RawSizeCheck& c) {
  if (c.files == 0) return c.problem;
  if (c.matches()) return {};
  if (c.filesWanted != 0 && c.filesWanted != c.files) {
    int off = c.files - c.filesWanted;
    return "the folder has " + std::to_string(c.files) + " slice files, the layout " +
           std::to_string(c.filesWanted) + " (" + std::to_string(std::abs(off)) + " file(s) " +
           (off > 0 ? "too many" : "missing") + ")";
  }
  const bool longer = c.actualBytes > c.expectedBytes;
  const uint64_t off = longer ? c.actualBytes - c.expectedBytes : c.expectedBytes - c.actualBytes;
  std::string text = (c.files > 1 ? c.file + " is " : "the file is ") + std::to_string(off) +
                     " bytes too " + (longer ? "long" : "short");
  if (c.files == 1 && c.sliceBytes > 0) {  // a folder's files hold one slice each
    char slices[32];
    double n = double(off) / double(c.sliceBytes);
    std::snprintf(slices, sizeof slices, n == std::floor(n) ? "%.0f" : "%.2f", n);
    text += std::string(" (") + slices + " slices)";
  }
  return text;
}

std::optional<std::vector<double>> readMiddleRawSlice(const std::string& input,
                                                      const RawLayout& l) {
  if (l.dims.x <= 0 || l.dims.y <= 0) return std::nullopt;
  const size_t count = size_t(l.dims.x) * size_t(l.dims.y);
  const size_t sliceBytes = count * sampleBytes(l.type);
  std::string file = input;
  size_t offset = l.headerBytes;
  std::error_code ec;
  try {
    if (fs::is_directory(input, ec) || isPattern(input)) {
      auto files = stackFiles(input, l);
      file = files[files.size() / 2].path;  // never empty: an empty folder throws
    } else {
      offset += sliceBytes * size_t(std::max(l.dims.z, 1) / 2);
    }
  } catch (const Error&) {
    return std::nullopt;
  }
  std::ifstream in(file, std::ios::binary);
  std::vector<uint8_t> bytes(sliceBytes);
  in.seekg(std::streamoff(offset));
  if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(sliceBytes)))
    return std::nullopt;
  RawLayout raw = l;  // values before the rescale
  raw.slope = 1.0;
  raw.intercept = 0.0;
  std::vector<double> values(count);
  detail::decodeSamples(bytes.data(), count, detail::decodingOf(raw), values.data());
  return values;
}

}  // namespace voxray
