#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "voxray/io/error.h"
#include "voxray/io/image.h"
#include "voxray/io/temporary_file.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string orUnknown(std::string reason) { return reason.empty() ? "unknown error" : reason; }

void writeTo(const fs::path& file, const std::string& shownPath, const Image& image) {
  auto out = OIIO::ImageOutput::create(file.string());
  if (!out) {
    throw outputError(shownPath + ": cannot write this kind of image (" +
                      orUnknown(OIIO::geterror()) + "); use .png, .tif or .exr");
  }
  // EXR is a float format: half keeps 8-bit values exactly (as 0..1).
  const bool floating = lower(file.extension().string()) == ".exr";
  OIIO::ImageSpec spec(image.width, image.height, 4,
                       floating ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8);
  // Our pixels are straight (not premultiplied) alpha: store them as they are.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(file.string(), spec) ||
      !out->write_image(OIIO::TypeDesc::UINT8, image.rgba.data()) || !out->close()) {
    throw outputError(shownPath + ": " + orUnknown(out->geterror()));
  }
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
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // keep straight alpha, as written
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) throw inputError(path + ": cannot read the image (" + orUnknown(OIIO::geterror()) + ")");
  const OIIO::ImageSpec& spec = in->spec();
  const int channels = spec.nchannels;
  if (spec.width <= 0 || spec.height <= 0 || channels <= 0) {
    throw inputError(path + ": the image has no pixels");
  }
  std::vector<uint8_t> pixels(size_t(spec.width) * size_t(spec.height) * size_t(channels));
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data())) {
    throw inputError(path + ": cannot read the image (" + orUnknown(in->geterror()) + ")");
  }

  // Gray, gray + alpha, RGB and RGBA (extra channels dropped) all become RGBA.
  Image image(spec.width, spec.height);
  const size_t count = size_t(spec.width) * size_t(spec.height);
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
