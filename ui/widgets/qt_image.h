#pragma once
// Conversions between the engine's RGBA8 Image and QImage.
#include <QImage>

#include "voxray/io/image.h"

namespace voxray::ui {

QImage toQImage(const Image& image);  // a deep copy
Image fromQImage(const QImage& image);

}  // namespace voxray::ui
