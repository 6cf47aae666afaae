#pragma once
// Rigid motions for the compare and fusion tests, through GLM: a turn of DEGREES about AXIS
// (right-handed) and the 4 x 4 of a turn followed by a translation.
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace voxray::test {

inline glm::dmat3 rotation(glm::dvec3 axis, double degrees) {
  return glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::normalize(axis)));
}

inline glm::dmat4 rigid(const glm::dmat3& r, const glm::dvec3& t) {
  glm::dmat4 m(r);
  m[3] = glm::dvec4(t, 1.0);
  return m;
}

// The point P moved by the 4 x 4 M.
inline glm::dvec3 applyRigid(const glm::dmat4& m, const glm::dvec3& p) {
  return glm::dvec3(m * glm::dvec4(p, 1.0));
}

}  // namespace voxray::test
