// Image I/O for lean builds configured with VOXRAY_WITH_OIIO=OFF (benchmarks carried to
// machines that lack OpenImageIO's 260 libraries): PNG only, through libpng's simplified API
// (one library beside the program); other formats say how to get the full set.
#include <png.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "voxray/io/error.h"
#include "voxray/io/image.h"

namespace voxray {
namespace {

bool isPng(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png";
}

std::string onlyPng(const std::string& path, const char* verb) {
  return path + ": this build " + verb +
         " PNG only (configured with VOXRAY_WITH_OIIO=OFF); name a .png file or use a default "
         "build";
}

}  // namespace

void writeImage(const std::string& path, const Image& image) {
  if (!isPng(path)) throw outputError(onlyPng(path, "writes"));
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(image.width);
  png.height = png_uint_32(image.height);
  png.format = PNG_FORMAT_RGBA;
  // As the OpenImageIO path: a temporary file beside the target, then a rename.
  const std::string tmp = path + ".part";
  if (!png_image_write_to_file(&png, tmp.c_str(), 0, image.rgba.data(), 0, nullptr)) {
    const std::string why = png.message;
    std::remove(tmp.c_str());
    throw outputError(path + ": cannot write the PNG (" + why + ")");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw outputError(path + ": cannot write it (" + ec.message() + ")");
  }
}

Image readImage(const std::string& path) {
  if (!isPng(path)) throw inputError(onlyPng(path, "reads"));
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str()))
    throw inputError(path + ": not a readable PNG (" + png.message + ")");
  png.format = PNG_FORMAT_RGBA;
  Image image(int(png.width), int(png.height));
  if (!png_image_finish_read(&png, nullptr, image.rgba.data(), 0, nullptr)) {
    const std::string why = png.message;
    png_image_free(&png);
    throw inputError(path + ": cannot read the PNG (" + why + ")");
  }
  return image;
}

}  // namespace voxray
