// Image files through OpenImageIO, loaded from libvoxray_oiio.so on first use
// (image/oiio_codec.h says why it is not linked).
#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <new>
#include <system_error>

#include "image/oiio_codec.h"
#include "module/program_module.h"
#include "voxray/io/error.h"
#include "voxray/io/image.h"
#include "voxray/io/temporary_file.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

// The module's functions, or why they could not be loaded.
struct Codec {
  decltype(&voxray_oiio_write) write = nullptr;
  decltype(&voxray_oiio_read) read = nullptr;
  std::string missing;  // empty when loaded
};

Codec loadCodec() {
  Codec c;
  const char* symbols[] = {"voxray_oiio_write", "voxray_oiio_read", nullptr};
  void* handle =
      loadProgramModule("libvoxray_oiio.so", "OpenImageIO", "voxray_oiio", symbols, &c.missing);
  if (!handle) return c;
  c.write = reinterpret_cast<decltype(c.write)>(dlsym(handle, "voxray_oiio_write"));
  c.read = reinterpret_cast<decltype(c.read)>(dlsym(handle, "voxray_oiio_read"));
  return c;
}

const Codec& codec() {
  static const Codec c = loadCodec();  // once, thread-safe
  return c;
}

void writeTo(const fs::path& file, const std::string& shownPath, const Image& image) {
  const Codec& c = codec();
  if (!c.write) throw outputError(shownPath + ": " + c.missing);
  char why[1024] = {};
  const int result =
      c.write(file.c_str(), image.width, image.height, image.rgba.data(), why, sizeof why);
  if (result == 1)
    throw outputError(shownPath + ": cannot write this kind of image (" + why +
                      "); use .png, .tif or .exr");
  if (result != 0) throw outputError(shownPath + ": " + why);
}

// TARGET exists and is no regular file: encode in the temporary folder (by TARGET's
// extension, PNG without one), then copy the bytes into TARGET as a stream.
void writeIntoSpecial(const fs::path& target, const std::string& shownPath, const Image& image) {
  fs::path named = target.filename();
  if (named.extension().empty()) named += ".png";
  std::error_code ec;
  const fs::path encoded = temporaryBeside(fs::temp_directory_path(ec) / named);
  try {
    writeTo(encoded, shownPath, image);
    std::ifstream in(encoded, std::ios::binary);
    std::ofstream out(target, std::ios::binary);
    if (!(out << in.rdbuf()) || !out.flush())
      throw outputError(shownPath + ": cannot write into it (it is not a regular file)");
  } catch (...) {
    fs::remove(encoded, ec);
    throw;
  }
  fs::remove(encoded, ec);
}

}  // namespace

void writeImage(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != size_t(image.width) * size_t(image.height) * 4) {
    throw outputError(path + ": the image to write is empty or its pixel buffer has the " +
                      "wrong size (an internal error)");
  }
  const fs::path target(path);
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    throw outputError(path + ": the folder " + folder.string() + " does not exist");
  }
  if (target.filename().empty() || fs::is_directory(target, ec)) {
    throw outputError(path + ": this is a folder; give a file name like render.png");
  }

  // A device or a pipe (/dev/null, a FIFO) stays what it is: the image is encoded aside
  // and its bytes written into it, never renamed over it.
  const fs::file_status status = fs::status(target, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    writeIntoSpecial(target, path, image);
    return;
  }
  // Readers of `path` see the old image or the new one, never half a file.
  const fs::path temporary = temporaryBeside(target);
  try {
    writeTo(temporary, path, image);
    fs::rename(temporary, target, ec);
    if (ec) throw outputError(path + ": cannot replace the file (" + ec.message() + ")");
  } catch (...) {
    fs::remove(temporary, ec);
    throw;
  }
}

Image readImage(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw inputError(path + ": no such image file");
  const Codec& c = codec();
  if (!c.read) throw inputError(path + ": cannot read the image (" + c.missing + ")");
  struct Pixels {
    std::vector<uint8_t> bytes;
    int width = 0, height = 0, channels = 0;
  } read;
  auto allocate = [](void* context, int width, int height, int channels) -> uint8_t* {
    auto* p = static_cast<Pixels*>(context);
    try {  // no exception crosses into the module
      p->bytes.resize(size_t(width) * size_t(height) * size_t(channels));
    } catch (const std::bad_alloc&) {
      return nullptr;
    }
    *p = {std::move(p->bytes), width, height, channels};
    return p->bytes.data();
  };
  char why[1024] = {};
  const int result = c.read(path.c_str(), allocate, &read, why, sizeof why);
  if (result == 3) throw inputError(path + ": the image has no pixels");
  if (result != 0) throw inputError(path + ": cannot read the image (" + why + ")");
  const int channels = read.channels;
  const std::vector<uint8_t>& pixels = read.bytes;

  // Gray, gray + alpha, RGB and RGBA (extra channels dropped) all become RGBA.
  Image image(read.width, read.height);
  const size_t count = size_t(read.width) * size_t(read.height);
  for (size_t i = 0; i < count; ++i) {
    const uint8_t* p = &pixels[i * size_t(channels)];
    uint8_t* q = &image.rgba[i * 4];
    const bool gray = channels < 3;
    q[0] = p[0];
    q[1] = gray ? p[0] : p[1];
    q[2] = gray ? p[0] : p[2];
    q[3] = channels == 2 ? p[1] : (channels >= 4 ? p[3] : 255);
  }
  return image;
}

}  // namespace voxray
