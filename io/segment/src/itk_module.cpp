// The ITK module's entry point (itk_module.h): the operation, its errors caught here.
#include "itk_module.h"

#include <exception>

extern "C" __attribute__((visibility("default"))) int voxray_itk_run(
    int operation, voxray::itk_ops::Block* block, const int radius[3], int fullyConnected,
    voxray::itk_ops::Islands* islands, std::string* why) {
  namespace ops = voxray::itk_ops;
  const glm::ivec3 r(radius[0], radius[1], radius[2]);
  try {
    switch (operation) {
      case kVoxrayItkIslands:
        *islands = ops::islands(*block, fullyConnected != 0);
        break;
      case kVoxrayItkMedian:
        ops::median(*block, r);
        break;
      case kVoxrayItkClosing:
        ops::closing(*block, r);
        break;
      case kVoxrayItkOpening:
        ops::opening(*block, r);
        break;
      case kVoxrayItkFillHoles:
        ops::fillHoles(*block);
        break;
      default:
        *why = "unknown operation " + std::to_string(operation);
        return 1;
    }
    return 0;
  } catch (const std::exception& e) {  // ITK's exceptions, bad_alloc
    *why = e.what();
    return 1;
  }
}
