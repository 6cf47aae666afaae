#include "voxray/io/orientation.h"

#include <cctype>
#include <cmath>

#include "voxray/io/error.h"

namespace voxray {

glm::dmat3 directionFromAxesCode(const std::string& code) {
  auto bad = [&] {
    return inputError("orientation '" + code +
                      "': expected three letters from L/R, A/P, S/I, one per patient axis, "
                      "e.g. LPS or LPI");
  };
  if (code.size() != 3) throw bad();
  glm::dmat3 d(0.0);
  bool used[3] = {false, false, false};
  for (int k = 0; k < 3; ++k) {
    char c = char(std::toupper(static_cast<unsigned char>(code[size_t(k)])));
    int axis = (c == 'L' || c == 'R')   ? 0
               : (c == 'A' || c == 'P') ? 1
               : (c == 'S' || c == 'I') ? 2
                                        : -1;
    if (axis < 0 || used[axis]) throw bad();
    used[axis] = true;
    d[k][axis] = (c == 'L' || c == 'P' || c == 'S') ? 1.0 : -1.0;
  }
  return d;
}

std::string axesCodeFromDirection(const glm::dmat3& direction) {
  static const char pos[3] = {'L', 'P', 'S'}, neg[3] = {'R', 'A', 'I'};
  std::string code;
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3& c = direction[k];
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (std::abs(c[a]) > std::abs(c[axis])) axis = a;
    code += c[axis] >= 0.0 ? pos[axis] : neg[axis];
  }
  return code;
}

}  // namespace voxray
