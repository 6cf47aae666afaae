#include "slice_geometry.h"

#include <cmath>

#include "voxray/engine/measure.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

// Screen x, screen y and normal as (patient axis, sign) for each orientation.
struct Wanted {
  int axis;
  double sign;
};
struct ViewAxes {
  Wanted u, v, n;
};

ViewAxes wanted(Orientation o) {
  switch (o) {
    case Orientation::Axial:  // right = patient left (+x), down = posterior (+y)
      return {{0, 1}, {1, 1}, {2, 1}};
    case Orientation::Coronal:  // right = patient left, down = inferior (-z)
      return {{0, 1}, {2, -1}, {1, 1}};
    case Orientation::Sagittal:  // right = posterior (+y), down = inferior
      return {{1, 1}, {2, -1}, {0, 1}};
  }
  return {{0, 1}, {1, 1}, {2, 1}};
}

// Letter at the end of a patient axis that the positive (or negative) direction points to.
std::string letter(int patientAxis, double sign) {
  static const char* pos[] = {"L", "P", "S"};
  static const char* neg[] = {"R", "A", "I"};
  return sign > 0 ? pos[patientAxis] : neg[patientAxis];
}

// The voxel axis whose direction is closest to the patient axis, skipping TAKEN.
int closestVoxelAxis(const glm::dmat3& dir, int patientAxis, int taken1, int taken2) {
  int best = -1;
  double bestDot = -1;
  for (int a = 0; a < 3; ++a) {
    if (a == taken1 || a == taken2) continue;
    double d = std::abs(dir[a][patientAxis]);
    if (d > bestDot) {
      bestDot = d;
      best = a;
    }
  }
  return best;
}

}  // namespace

const char* toString(Orientation o) {
  switch (o) {
    case Orientation::Axial:
      return "axial";
    case Orientation::Coronal:
      return "coronal";
    case Orientation::Sagittal:
      return "sagittal";
  }
  return "?";
}

PatientAxes patientAxes(Orientation o) {
  const ViewAxes w = wanted(o);
  auto unit = [](Wanted a) {
    glm::dvec3 d(0.0);
    d[a.axis] = a.sign;
    return d;
  };
  return {unit(w.u), unit(w.v), unit(w.n)};
}

SliceAxes sliceAxes(const glm::dmat3& direction, Orientation o) {
  ViewAxes w = wanted(o);
  SliceAxes a;
  a.orientation = o;
  a.nAxis = closestVoxelAxis(direction, w.n.axis, -1, -1);
  a.uAxis = closestVoxelAxis(direction, w.u.axis, a.nAxis, -1);
  a.vAxis = closestVoxelAxis(direction, w.v.axis, a.nAxis, a.uAxis);
  a.uFlip = direction[a.uAxis][w.u.axis] * w.u.sign < 0;
  a.vFlip = direction[a.vAxis][w.v.axis] * w.v.sign < 0;
  a.labels = {letter(w.u.axis, -w.u.sign), letter(w.u.axis, w.u.sign), letter(w.v.axis, -w.v.sign),
              letter(w.v.axis, w.v.sign)};
  return a;
}

glm::dvec3 sliceToVoxel(const SliceAxes& a, const glm::ivec3& dims, double u, double v,
                        double slice) {
  glm::dvec3 voxel(0.0);
  // Voxel centres sit at integers; slice pixel k covers [k, k+1) on screen.
  voxel[a.uAxis] = a.uFlip ? dims[a.uAxis] - u - 0.5 : u - 0.5;
  voxel[a.vAxis] = a.vFlip ? dims[a.vAxis] - v - 0.5 : v - 0.5;
  voxel[a.nAxis] = slice;
  return voxel;
}

glm::dvec2 voxelToSlice(const SliceAxes& a, const glm::ivec3& dims, const glm::dvec3& voxel) {
  double u = a.uFlip ? dims[a.uAxis] - 0.5 - voxel[a.uAxis] : voxel[a.uAxis] + 0.5;
  double v = a.vFlip ? dims[a.vAxis] - 0.5 - voxel[a.vAxis] : voxel[a.vAxis] + 0.5;
  return {u, v};
}

glm::dvec3 voxelToPatientMm(const Volume& v, const glm::dvec3& voxel) {
  return voxelToPatient(v, voxel);  // one mapping for the views and the measurements
}

glm::dvec3 voxelToWorldMm(const Volume& v, const glm::dvec3& voxel) {
  glm::dvec3 centre = (glm::dvec3(v.dims) - 1.0) * 0.5;
  return v.direction * ((voxel - centre) * v.spacingMm);
}

}  // namespace voxray
