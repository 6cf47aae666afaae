// voxray_image_compare REFERENCE CANDIDATE MEAN FRACTION LEVEL
// Passes when the mean absolute difference over RGB is <= MEAN (8-bit levels) and at most
// FRACTION of the pixels differ by more than LEVEL in any channel. A missing reference
// fails and says where the candidate is, so a new test cannot pass by accident.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "voxray/io/error.h"
#include "voxray/io/image.h"

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: %s REFERENCE CANDIDATE MEAN FRACTION LEVEL\n", argv[0]);
    return 2;
  }
  std::string refPath = argv[1], candPath = argv[2];
  double maxMean = std::atof(argv[3]), maxFraction = std::atof(argv[4]);
  int level = std::atoi(argv[5]);
  if (!std::filesystem::exists(refPath)) {
    std::fprintf(stderr, "no reference %s: check the candidate %s and copy it there if right\n",
                 refPath.c_str(), candPath.c_str());
    return 1;
  }
  try {
    voxray::Image ref = voxray::readImage(refPath), cand = voxray::readImage(candPath);
    if (ref.width != cand.width || ref.height != cand.height) {
      std::fprintf(stderr, "size differs: reference %dx%d, candidate %dx%d\n", ref.width,
                   ref.height, cand.width, cand.height);
      return 1;
    }
    size_t n = size_t(ref.width) * size_t(ref.height), over = 0;
    double sum = 0.0;
    int worst = 0;
    for (size_t i = 0; i < n; ++i) {
      int w = 0;
      for (int c = 0; c < 3; ++c) {
        int e = std::abs(int(ref.rgba[i * 4 + c]) - int(cand.rgba[i * 4 + c]));
        sum += e;
        w = std::max(w, e);
      }
      worst = std::max(worst, w);
      over += w > level;
    }
    double mean = sum / double(3 * n), fraction = double(over) / double(n);
    bool ok = mean <= maxMean && fraction <= maxFraction;
    std::printf(
        "%s: mean %.4f levels (limit %.4f), %.5f of pixels over %d levels (limit %.5f), "
        "max %d\n",
        ok ? "match" : "MISMATCH", mean, maxMean, fraction, level, maxFraction, worst);
    return ok ? 0 : 1;
  } catch (const voxray::Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
