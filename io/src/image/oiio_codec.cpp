// libvoxray_oiio.so: the OpenImageIO calls of image_io.cpp, loaded when first needed
// (oiio_codec.h says why).
#include "oiio_codec.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>

namespace {

int fail(int code, const std::string& reason, char* why, size_t whySize) {
  std::snprintf(why, whySize, "%s", reason.empty() ? "unknown error" : reason.c_str());
  return code;
}

}  // namespace

extern "C" int voxray_oiio_write(const char* file, int width, int height, const uint8_t* rgba,
                                 char* why, size_t whySize) {
  auto out = OIIO::ImageOutput::create(file);
  if (!out) return fail(1, OIIO::geterror(), why, whySize);
  std::string extension = file;
  extension = extension.substr(std::min(extension.size(), extension.rfind('.')));
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  // EXR is a float format: half keeps 8-bit values exactly (as 0..1).
  const bool floating = extension == ".exr";
  OIIO::ImageSpec spec(width, height, 4, floating ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8);
  // Our pixels are straight (not premultiplied) alpha: store them as they are.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(file, spec) || !out->write_image(OIIO::TypeDesc::UINT8, rgba) || !out->close())
    return fail(2, out->geterror(), why, whySize);
  return 0;
}

extern "C" int voxray_oiio_read(const char* path, VoxrayOiioAllocate allocate, void* context,
                                char* why, size_t whySize) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // keep straight alpha, as written
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) return fail(2, OIIO::geterror(), why, whySize);
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    return fail(3, "the image has no pixels", why, whySize);
  uint8_t* pixels = allocate(context, spec.width, spec.height, spec.nchannels);
  if (!pixels) return fail(2, "no memory for its pixels", why, whySize);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, pixels))
    return fail(2, in->geterror(), why, whySize);
  return 0;
}
