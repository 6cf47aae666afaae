#pragma once
// What the files of a folder that are not DICOM are, so that the skipped-files note says it
// ("401 TIFF images (not DICOM): ...") and what to do with them, rather than only
// "401 file(s) skipped: not a DICOM file".
#include <string>

namespace voxray::dicom {

// A short name of what PATH holds, from its first bytes (and its name for the volume
// formats): "TIFF", "PNG", "JPEG", "NIfTI", ...; empty when it is none Voxray knows.
std::string notDicomKind(const std::string& path);

// The note for COUNT files of KIND (notDicomKind, not empty): what they are and how to open
// them, e.g. "3 TIFF images (not DICOM): ...".
std::string notDicomNote(const std::string& kind, int count);

}  // namespace voxray::dicom
