// MP4 (H.264) movies through libvoxray_mp4.so, loaded on the first movie written
// (mp4_module.h says why FFmpeg is a module). Here: the file's place (written aside, renamed
// when complete, removed when not) and the messages.
#include <dlfcn.h>

#include <filesystem>
#include <system_error>

#include "../module/program_module.h"
#include "mp4_module.h"
#include "mp4_writer.h"
#include "voxray/io/error.h"
#include "voxray/io/temporary_file.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

// The module's functions, or why they could not be loaded.
struct Module {
  decltype(&voxray_mp4_open) open = nullptr;
  decltype(&voxray_mp4_push) push = nullptr;
  decltype(&voxray_mp4_finish) finish = nullptr;
  decltype(&voxray_mp4_close) close = nullptr;
  std::string missing;  // empty when loaded
};

Module loadModule() {
  Module m;
  const char* symbols[] = {"voxray_mp4_open", "voxray_mp4_push", "voxray_mp4_finish",
                           "voxray_mp4_close", nullptr};
  void* handle = loadProgramModule("libvoxray_mp4.so", "FFmpeg", "voxray_mp4", symbols, &m.missing);
  if (!handle) return m;
  m.open = reinterpret_cast<decltype(m.open)>(dlsym(handle, "voxray_mp4_open"));
  m.push = reinterpret_cast<decltype(m.push)>(dlsym(handle, "voxray_mp4_push"));
  m.finish = reinterpret_cast<decltype(m.finish)>(dlsym(handle, "voxray_mp4_finish"));
  m.close = reinterpret_cast<decltype(m.close)>(dlsym(handle, "voxray_mp4_close"));
  return m;
}

const Module& module() {
  static const Module m = loadModule();  // once, thread-safe
  return m;
}

// The module's writer and the file being written, released in any case: also when the
// writer's constructor throws half way (a member's destructor runs then, the writer's does
// not). Unfinished: no file.
struct Written {
  const Module& m;
  fs::path temporary;
  VoxrayMp4* movie = nullptr;
  bool finished = false;

  explicit Written(const Module& module) : m(module) {}
  Written(const Written&) = delete;
  Written& operator=(const Written&) = delete;
  ~Written() {
    if (m.close) m.close(movie);
    std::error_code ec;
    if (!finished && !temporary.empty()) fs::remove(temporary, ec);
  }
};

class Mp4Writer : public MovieWriter {
 public:
  Mp4Writer(const std::string& path, const MovieSettings& s) : path_(path), s_(s) {
    std::error_code ec;
    const fs::path folder = fs::path(path).parent_path();
    if (!folder.empty() && !fs::is_directory(folder, ec))
      throw outputError(path + ": the folder " + folder.string() + " does not exist");
    if (!m_.open) throw outputError(path + ": cannot write MP4 movies (" + m_.missing + ")");
    out_.temporary = temporaryBeside(path);
    char why[1024] = {};
    const int r = m_.open(out_.temporary.c_str(), s.size.width, s.size.height, s.fps, s.crf,
                          &out_.movie, why, sizeof why);
    if (r == 1)
      throw outputError(path + ": this FFmpeg build has no H.264 encoder (libx264); " +
                        "install Debian's libavcodec59, or write PNG frames (-o frames/)");
    check(r, why);
  }
  void push(const Image& image) override {
    if (image.width != s_.size.width || image.height != s_.size.height)
      throw outputError(path_ + ": a movie frame has the wrong size (an internal error)");
    char why[1024] = {};
    check(m_.push(out_.movie, image.rgba.data(), why, sizeof why), why);
  }

  void finish() override {
    char why[1024] = {};
    check(m_.finish(out_.movie, why, sizeof why), why);
    std::error_code ec;
    fs::rename(out_.temporary, path_, ec);
    if (ec) throw outputError(path_ + ": cannot replace the file (" + ec.message() + ")");
    out_.finished = true;
  }

 private:
  void check(int code, const char* why) const {
    if (code != 0) throw outputError(path_ + ": " + why);
  }

  const Module& m_ = module();
  std::string path_;
  MovieSettings s_;
  Written out_{m_};
};

}  // namespace

std::unique_ptr<MovieWriter> openMp4Writer(const std::string& path, const MovieSettings& s) {
  return std::make_unique<Mp4Writer>(path, s);
}

}  // namespace voxray
