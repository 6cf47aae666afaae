#pragma once
// Screenshots as DICOM: a Multi-frame True Color Secondary Capture (the single-frame SC IOD
// is retired in PS3.3), written with DCMTK, in the study of the volume it shows, as a new
// series, so that a PACS files it with that study.
#include <string>
#include <vector>

#include "voxray/io/image.h"
#include "voxray/io/volume.h"

namespace voxray {

struct SecondaryCaptureInfo {
  // The study it belongs to: Study Instance UID, date, time, accession, description. The
  // patient module (name, ID, birth date) is copied into the header too, because a PACS
  // files an instance by patient and study; the pixels carry no patient text.
  StudyIdentity study;
  std::string seriesDescription = "Voxray 3D";
  std::string seriesInstanceUid;    // empty: a new series
  bool burnedInAnnotation = false;  // true when the frames show text or labels
};

// Writes FRAMES (all the same size, RGBA; alpha is dropped) into PATH, atomically. Returns the
// new SOP Instance UID. Throws Error (Input) for no or unequal frames, (Output) when the
// file cannot be written.
std::string writeSecondaryCapture(const std::string& path, const std::vector<Image>& frames,
                                  const SecondaryCaptureInfo& info);

}  // namespace voxray
