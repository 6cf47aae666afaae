#pragma once
// DICOM series of known phantoms, written with DCMTK, for what the shared data lacks: a PET
// sphere of known activity (its SUV known exactly) and a beating sphere (a 4D CT whose
// sphere radius changes per phase). Each file is a complete PET or CT Image object
// (dciodvfy finds no error). The phantom's patient is made up ("PHANTOM^VOXRAY").
#include <set>
#include <string>

#include <glm/glm.hpp>

namespace voxray {

struct PetSpherePhantom {
  glm::ivec3 dims{48, 48, 32};
  glm::dvec3 spacingMm{4.0, 4.0, 4.0};
  double radiusMm = 36.0;  // the sphere, centred in the volume
  // Activity concentration in the images (Bq/mL, decay-corrected as decayCorrection says).
  int insideBqml = 21000, backgroundBqml = 2500;
  double weightKg = 72.5;
  double injectedDoseBq = 370e6;
  double halfLifeS = 6586.2;  // fluorine-18: 109.77 min
  std::string decayCorrection = "START";
  std::string seriesDate = "20260115", seriesTime = "104500";
  std::string acquisitionTime = "104500";  // every image's
  std::string injectionTime = "093000";    // Radiopharmaceutical Start Time (TM)
  std::string injectionDateTime;           // Radiopharmaceutical Start DateTime; empty: none
  // DICOM keywords of attributes to leave out (PatientWeight, Units, DecayCorrection,
  // RadionuclideTotalDose, RadionuclideHalfLife, RadiopharmaceuticalStartTime, SeriesTime):
  // the objects are then incomplete on purpose, for the tests of SUV's messages.
  std::set<std::string> omit;
};

// The SUVbw of the sphere's voxels from P's own numbers (QIBA: the dose decayed from the
// injection to the series time for START, as injected for ADMIN).
double petSphereSuv(const PetSpherePhantom& p);

struct BeatingSpherePhantom {
  glm::ivec3 dims{64, 64, 32};
  glm::dvec3 spacingMm{1.5, 1.5, 3.0};
  int phases = 10;
  double radiusMm = 24.0, amplitudeMm = 8.0;  // phase t: radius + amplitude sin(2 pi t / phases)
  int insideHu = 300, outsideHu = -50;
  // How the phases are told apart: "temporal" (Temporal Position Identifier), "trigger"
  // (Trigger Time only, instance numbers backwards) or "repeated" (positions repeated,
  // phases in instance-number order).
  std::string timing = "temporal";
  double radiusAt(int phase) const;
};

// Writes one file per image into DIR (created; must not hold files already). Throws Error
// (Output) when it cannot write, (Input) for a bad phantom.
void writePetSpherePhantom(const std::string& dir, const PetSpherePhantom& p = {});
void writeBeatingSpherePhantom(const std::string& dir, const BeatingSpherePhantom& p = {});

}  // namespace voxray
