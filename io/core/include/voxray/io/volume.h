#pragma once
// A scalar volume with its physical geometry. Voxels are stored as 16-bit integers
// (x fastest, then y, then z); the physical value (HU for CT, scanner units for MR)
// is stored * slope + intercept, so a non-integral DICOM slope keeps its precision
// without a float copy.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/io/voxel_memory.h"

namespace voxray {

// The window the data asks to be shown with (DICOM WindowCenter/WindowWidth, the first
// pair), in physical units like every value of the volume.
struct DisplayWindow {
  double width = 0.0;
  double level = 0.0;
  std::string explanation;  // WindowCenterWidthExplanation (its first value), may be empty
  std::string origin = "DICOM window";  // where it came from, as the UI names it
};

// Who and what the volume shows, from the source's headers (DICOM; empty for raw files).
// Identifying fields are for display on the user's request only: never put them into logs,
// messages, file names or exports by default.
struct StudyIdentity {
  std::string patientName, patientId, patientBirthDate;  // identifying
  std::string studyInstanceUid, studyDate, studyTime, studyDescription, accessionNumber;
  std::string studyId;  // StudyID, the site's short study number
  std::string seriesInstanceUid, seriesDescription, frameOfReferenceUid;
  int seriesNumber = 0;
  // What a derived object (a DICOM SEG) references: the images' SOP Class and, per slice k
  // of the volume, its SOP Instance UID. Empty when the volume's slices are not the files'
  // (resampled for tilt or uneven gaps, or frames of one multi-frame file): then only the
  // series can be referenced.
  std::string sopClassUid;
  std::vector<std::string> sliceSopInstanceUids;
};

// PET: how a value in Bq/mL becomes an SUV (QIBA's SUVbw: body weight over the injected dose
// decay-corrected to the scan's start). SUV = physical value * factor.
struct SuvScale {
  double factor = 1.0;  // g/mL per Bq/mL: weight (g) / decay-corrected injected dose (Bq)
  std::string unit = "SUVbw";
  double toSuv(double physical) const { return physical * factor; }
};

struct Volume {
  glm::ivec3 dims{0};         // columns (i), rows (j), slices (k)
  glm::dvec3 spacingMm{1.0};  // distance between voxel centres along i, j, k
  glm::dvec3 originMm{0.0};   // LPS position of the centre of voxel (0,0,0)
  glm::dmat3 direction{1.0};  // columns: LPS unit vectors of the i, j, k axes
  double slope = 1.0;         // physical = stored * slope + intercept
  double intercept = 0.0;
  std::string unit = "HU";
  std::string modality;                 // DICOM Modality ("CT", "MR", ...); empty: not known
  std::optional<DisplayWindow> window;  // none when the source gives no window
  StudyIdentity study;
  std::optional<SuvScale> suv;  // PET with every attribute SUV needs; none: values as stored
  int timePoint = 0;            // 4D: which time point this is (0-based) of timePoints
  int timePoints = 1;
  std::string sourceType = "i16";     // sample type it was read from
  std::vector<std::string> warnings;  // things the user should know (clamping, NaN, ...)
  VoxelVector voxels;  // 2 MiB-aligned huge pages where Linux gives them (voxel_memory.h)

  size_t voxelCount() const { return size_t(dims.x) * size_t(dims.y) * size_t(dims.z); }
  size_t byteSize() const { return voxelCount() * sizeof(int16_t); }
  size_t index(int x, int y, int z) const {
    return (size_t(z) * size_t(dims.y) + size_t(y)) * size_t(dims.x) + size_t(x);
  }
  int16_t at(int x, int y, int z) const { return voxels[index(x, y, z)]; }
  double toPhysical(double stored) const { return stored * slope + intercept; }
  double toStored(double physical) const { return (physical - intercept) / slope; }
  // Physical size of the volume's box: voxels are cells of one spacing each.
  glm::dvec3 extentMm() const { return glm::dvec3(dims) * spacingMm; }
  // The finest spacing: the unit of sample steps and of distances measured in voxels.
  double minSpacingMm() const { return std::min({spacingMm.x, spacingMm.y, spacingMm.z}); }
};

struct ValueRange {
  int16_t min = 0;
  int16_t max = 0;
};

// Smallest and largest stored value; {0, 0} for an empty volume.
ValueRange storedRange(const Volume& v);

}  // namespace voxray
