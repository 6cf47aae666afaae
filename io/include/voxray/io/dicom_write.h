#pragma once
// What Voxray's DICOM writers share (the Secondary Capture, the phantom series, the SR and
// KOS, the DICOM SEG, the anonymised copies): new UIDs, the local date and time, and the save
// that leaves a whole file or none. DCMTK's file type is only named here, so this header
// stays std-only; the writers include DCMTK themselves. Built with DICOM only.
#include <string>

class DcmFileFormat;

namespace voxray::dicomwrite {

// A new UID under ROOT (DCMTK's SITE_*_UID_ROOT).
std::string newUid(const char* root);

// The local time in strftime's FORMAT ("%Y%m%d" for a DA, "%H%M%S" for a TM).
std::string localNow(const char* format);

// How FILE is encoded: a new object in Explicit VR Little Endian, or a read file in its own
// transfer syntax with a new meta header (the old one names the source's instance and sender).
enum class Encoding { explicitLittleEndian, asReadNewMeta };

// Saves FILE beside PATH under a hidden temporary name, then renames it onto PATH, so an
// interrupted write leaves no half file there. On failure the temporary file is removed and
// an Output error says "Cannot write the WHAT PATH (why): ...".
void saveAtomically(DcmFileFormat& file, const std::string& path, const std::string& what,
                    Encoding encoding = Encoding::explicitLittleEndian);

}  // namespace voxray::dicomwrite
