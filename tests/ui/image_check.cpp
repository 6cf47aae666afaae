// Checks a screenshot of the workstation is not blank: the 3D view (top left quarter)
// must contain a rendered object (bright pixels with varied shades) and the whole window
// must show more than a couple of colours. Exit 0 on success, 1 with a reason otherwise.
#include <iostream>
#include <set>

#include "voxray/io/image.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: voxray_image_check IMAGE\n";
    return 2;
  }
  voxray::Image img = voxray::readImage(argv[1]);
  if (img.width < 400 || img.height < 300) {
    std::cerr << "image too small: " << img.width << "x" << img.height << "\n";
    return 1;
  }
  std::set<int> shades;
  int bright = 0;
  // The 3D view fills the top left quarter of the view grid (the panel is on the right).
  for (int y = img.height / 10; y < img.height / 2; ++y)
    for (int x = 0; x < img.width / 3; ++x) {
      const uint8_t* p = img.pixel(x, y);
      int grey = (p[0] + p[1] + p[2]) / 3;
      if (grey > 60) ++bright;
      shades.insert(grey);
    }
  std::set<uint32_t> colours;
  for (int y = 0; y < img.height; y += 3)
    for (int x = 0; x < img.width; x += 3) {
      const uint8_t* p = img.pixel(x, y);
      colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
    }
  std::cout << "3D view: " << bright << " bright pixels, " << shades.size()
            << " shades; window: " << colours.size() << " colours\n";
  if (bright < 500 || shades.size() < 20 || colours.size() < 50) {
    std::cerr << "screenshot looks blank\n";
    return 1;
  }
  return 0;
}
