#include "voxray/io/movie_writer.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <system_error>

#include "mp4_writer.h"
#include "voxray/io/error.h"
#include "voxray/io/temporary_file.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

// A sequence's names: PREFIX + the frame number with at least DIGITS digits + SUFFIX.
struct Numbering {
  std::string prefix, suffix;
  int digits = 1;
  std::string name(int k) const {
    char number[32];
    std::snprintf(number, sizeof number, "%0*d", digits, k);
    return prefix + number + suffix;
  }
};

bool endsWith(const std::string& s, const std::string& end) {
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

// "%d" or "%0Nd" exactly once; nullopt when PATH has no '%'. Throws for other uses of '%'.
std::optional<Numbering> patternNumbering(const std::string& path) {
  const size_t at = path.find('%');
  if (at == std::string::npos) return std::nullopt;
  size_t i = at + 1;
  int digits = 1;
  if (i < path.size() && path[i] == '0') {
    digits = 0;
    for (++i; i < path.size() && std::isdigit(static_cast<unsigned char>(path[i])); ++i)
      digits = std::min(digits * 10 + (path[i] - '0'), 9);
  }
  if (i >= path.size() || path[i] != 'd' || path.find('%', i) != std::string::npos || digits < 1) {
    throw outputError(path + ": a frame-name pattern takes one number, as %d or %04d (e.g. " +
                      "frames/%04d.png)");
  }
  Numbering n{path.substr(0, at), path.substr(i + 1), digits};
  if (!endsWith(n.suffix, ".png"))
    throw outputError(path + ": image sequences are PNG; end the pattern with .png");
  return n;
}

bool isFolderTarget(const std::string& path) {
  std::error_code ec;
  return endsWith(path, "/") || fs::is_directory(path, ec);
}

Numbering numbering(const std::string& path, int frames) {
  if (auto n = patternNumbering(path)) return *n;
  // A folder: 0000.png, 0001.png, ... (more digits for 10,000 frames and over).
  const int digits = std::max(4, int(std::to_string(std::max(frames - 1, 0)).size()));
  return {(fs::path(path) / "").string(), ".png", digits};
}

class SequenceWriter : public MovieWriter {
 public:
  // MAY_CREATE: the target is a folder ("frames/"), which may be new; a pattern's folder
  // must exist, as for writeImage.
  SequenceWriter(Numbering names, const MovieSettings& s, bool mayCreate)
      : names_(std::move(names)), s_(s) {
    const fs::path folder = fs::path(names_.name(0)).parent_path();
    std::error_code ec;
    if (folder.empty() || fs::is_directory(folder, ec)) return;
    if (!mayCreate || !fs::create_directories(folder, ec)) {
      throw outputError(names_.name(0) + ": the folder " + folder.string() +
                        (mayCreate ? " cannot be created (" + ec.message() + ")"
                                   : " does not exist; create it first"));
    }
    createdFolder_ = folder;
  }
  ~SequenceWriter() override {
    std::error_code ec;
    for (const auto& t : temporaries_) fs::remove(t, ec);
    if (!createdFolder_.empty()) fs::remove(createdFolder_, ec);  // only when left empty
  }
  void push(const Image& frame) override {
    if (frame.width != s_.size.width || frame.height != s_.size.height)
      throw outputError("a movie frame has the wrong size (an internal error)");
    const fs::path final = names_.name(int(temporaries_.size()));
    temporaries_.push_back(temporaryBeside(final));
    writeImage(temporaries_.back().string(), frame);
  }
  void finish() override {
    std::error_code ec;
    for (size_t k = 0; k < temporaries_.size(); ++k) {
      fs::rename(temporaries_[k], names_.name(int(k)), ec);
      if (ec) {
        throw outputError(names_.name(int(k)) + ": cannot replace the file (" + ec.message() + ")");
      }
    }
    temporaries_.clear();
    createdFolder_.clear();
  }

 private:
  Numbering names_;
  MovieSettings s_;
  std::vector<fs::path> temporaries_;
  fs::path createdFolder_;  // made by this writer: removed again on cancel when empty
};

}  // namespace

MovieFormat movieFormat(const std::string& path) {
  if (patternNumbering(path) || isFolderTarget(path)) return MovieFormat::ImageSequence;
  std::string ext = fs::path(path).extension().string();
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".mp4") return MovieFormat::Mp4;
  throw outputError(path + ": movies are written as .mp4, or as PNG frames to a folder " +
                    "(frames/) or a pattern (frames/%04d.png)");
}

MovieSize movieFrameSize(MovieFormat format, MovieSize requested) {
  if (format != MovieFormat::Mp4) return requested;
  return {requested.width + requested.width % 2, requested.height + requested.height % 2};
}

std::vector<std::string> movieFiles(const std::string& path, int frames) {
  if (movieFormat(path) == MovieFormat::Mp4) return {path};
  const Numbering n = numbering(path, frames);
  std::vector<std::string> files;
  for (int k = 0; k < frames; ++k) files.push_back(n.name(k));
  return files;
}

std::unique_ptr<MovieWriter> openMovieWriter(const std::string& path, const MovieSettings& s) {
  if (s.size.width <= 0 || s.size.height <= 0 || s.frames <= 0)
    throw outputError(path + ": a movie needs a frame size and at least one frame");
  const MovieSize stored = movieFrameSize(movieFormat(path), s.size);
  if (stored.width != s.size.width || stored.height != s.size.height)
    throw outputError(path + ": MP4 (H.264, 4:2:0) needs an even width and height");
  if (movieFormat(path) == MovieFormat::Mp4) return openMp4Writer(path, s);
  return std::make_unique<SequenceWriter>(numbering(path, s.frames), s, !patternNumbering(path));
}

}  // namespace voxray
