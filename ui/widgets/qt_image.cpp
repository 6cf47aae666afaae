#include "qt_image.h"

#include <cstring>

namespace voxray::ui {

QImage toQImage(const Image& image) {
  if (image.width <= 0 || image.height <= 0) return {};
  QImage wrapped(image.rgba.data(), image.width, image.height, image.width * 4,
                 QImage::Format_RGBA8888);
  return wrapped.copy();
}

Image fromQImage(const QImage& image) {
  QImage rgba = image.convertToFormat(QImage::Format_RGBA8888);
  Image out(rgba.width(), rgba.height());
  for (int y = 0; y < rgba.height(); ++y)
    std::memcpy(out.pixel(0, y), rgba.constScanLine(y), size_t(rgba.width()) * 4);
  return out;
}

}  // namespace voxray::ui
