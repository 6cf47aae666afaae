#pragma once
// DICOM series of known phantoms, written with DCMTK, for what the shared data lacks: a PET
// sphere of known activity (its SUV known exactly) and a beating sphere (a 4D CT whose
// sphere radius changes per phase). Each file is a complete PET or CT Image object
// (dciodvfy finds no error); the mosaic is an MR Image. The phantom's patient is made up
// ("PHANTOM^VOXRAY").
#include <optional>
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
  // GE's private scan DateTime (0009,100D) of creator GEMS_PETD_01, written when not empty: a
  // GE series re-made after the scan (its Series Time later than the acquisition) keeps the
  // scan's start there.
  std::string geScanDateTime;
  // DICOM keywords of attributes to leave out (PatientWeight, Units, DecayCorrection,
  // RadionuclideTotalDose, RadionuclideHalfLife, RadiopharmaceuticalStartTime, SeriesTime):
  // the objects are then incomplete on purpose, for the tests of SUV's messages.
  std::set<std::string> omit;
};

// The SUVbw of the sphere's voxels from P's own numbers (QIBA: the dose decayed from the
// injection to the scan's start for START, as injected for ADMIN; the scan's start is the
// series time, or GE's scan time or the acquisition time when the series is later).
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

// A Siemens mosaic fMRI run (issue 36): a known oblique volume per time point, its slices
// tiled into one MR image per time point as Siemens does (ceil(sqrt(N)) tiles a row, Image
// Position at the whole image's corner), with (0019,100A) NumberOfImagesInMosaic and a minimal
// CSA image header (NumberOfImagesInMosaic, SliceNormalVector).
struct MosaicPhantom {
  glm::ivec3 dims{40, 32, 14};          // a tile's columns and rows, the slices
  glm::dvec3 spacingMm{2.5, 3.0, 4.0};  // Pixel Spacing, Spacing Between Slices
  double sliceThicknessMm = 3.5;        // thinner than the spacing: a gap, as in fMRI
  int timePoints = 3;
  // Orientation: the axial axes turned 25 degrees about z (S), then 20 degrees about x (L).
  double yawDegrees = 25.0, pitchDegrees = 20.0;
  glm::dvec3 originMm{-48.5, -40.25, -20.0};   // LPS centre of voxel (0, 0, 0)
  glm::dvec3 sphereCentreMm{10.0, 5.0, 12.0};  // LPS, off the volume's centre
  double radiusMm = 16.0;
  // Written as they are when set (for the tests of bad input); else the slice count.
  std::optional<int> mrHeaderImages, csaImages;
  bool writeMrHeaderImages = true;  // (0019,100A); false: only the CSA header says it
  bool reverseSlices = false;       // tiles stored along -(row x column), SliceNormalVector says so
  glm::dmat3 axes() const;          // columns: the i, j, k directions (LPS unit vectors)
  glm::dvec3 position(glm::ivec3 ijk) const;       // LPS centre of voxel IJK
  int value(glm::ivec3 ijk, int timePoint) const;  // its stored value (no rescale)
};

// Writes one file per image into DIR (created; must not hold files already). Throws Error
// (Output) when it cannot write, (Input) for a bad phantom.
void writePetSpherePhantom(const std::string& dir, const PetSpherePhantom& p = {});
void writeBeatingSpherePhantom(const std::string& dir, const BeatingSpherePhantom& p = {});
void writeMosaicPhantom(const std::string& dir, const MosaicPhantom& p = {});

}  // namespace voxray
