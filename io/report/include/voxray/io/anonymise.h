#pragma once
// Anonymised export: every DICOM file of a folder (a series or a whole study) copied into
// another folder with the PS3.15 Basic Application Level Confidentiality Profile applied
// (Table E.1-1), through DCMTK. UIDs get new values, mapped consistently within one export so
// the series still opens as the same volume; private tags go; dates go, stay or shift.
#include <cstddef>
#include <string>
#include <vector>

namespace voxray {

enum class DateHandling { Remove, Keep, Shift };

struct AnonymiseOptions {
  DateHandling dates = DateHandling::Remove;
  int shiftDays = 0;      // DateHandling::Shift: days added to every DA and DT
  std::string seriesUid;  // only this series; empty: every DICOM file under the input
  std::string patientName = "ANONYMOUS";
  std::string patientId = "ANONYMOUS";
  bool force = false;  // write into an existing, non-empty output folder
};

struct AnonymiseResult {
  size_t written = 0;
  size_t skipped = 0;  // files that are not DICOM (or of another series)
  // Images whose pixels show text (Burned In Annotation YES): left out, because the Basic
  // Profile without its Clean Pixel Data option cannot clean them.
  size_t burnedIn = 0;
  std::vector<std::string> files;  // written, relative to the output folder
};

// Reads every file under INPUT (a folder, or one file), writes the de-identified copies into
// OUTPUT as SERIESNUMBER/IMnnnnn.dcm (names carry no patient text). Throws Error (Input) when
// INPUT has no DICOM file (of SERIESUID), OUTPUT lies inside INPUT (never write into the
// user's data) or OUTPUT exists and is not empty without force; (Output) when a file cannot
// be written.
AnonymiseResult anonymise(const std::string& input, const std::string& output,
                          const AnonymiseOptions& options);

}  // namespace voxray
