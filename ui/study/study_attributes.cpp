#include "study_attributes.h"

#include <filesystem>

#ifdef VOXRAY_HAS_DICOM
#include <dcmtk/dcmdata/dctk.h>
#endif

namespace voxray {

namespace fs = std::filesystem;

std::string seriesBodyPart(const std::string& input, const std::string& seriesUid, int maxFiles) {
#ifdef VOXRAY_HAS_DICOM
  std::error_code ec;
  auto bodyPartOf = [&](const fs::path& file, std::string& out) {
    DcmFileFormat f;
    // The header only: the pixels are not needed (and may be large).
    if (f.loadFileUntilTag(file.c_str(), EXS_Unknown, EGL_noChange, DCM_MaxReadLength,
                           ERM_autoDetect, DCM_PixelData)
            .bad())
      return false;
    OFString uid, part;
    if (!seriesUid.empty() &&
        (f.getDataset()->findAndGetOFString(DCM_SeriesInstanceUID, uid).bad() ||
         uid.c_str() != seriesUid))
      return false;
    f.getDataset()->findAndGetOFString(DCM_BodyPartExamined, part);
    out = part.c_str();
    return true;
  };
  std::string part;
  if (fs::is_regular_file(input, ec)) {
    bodyPartOf(input, part);
    return part;
  }
  int seen = 0;
  for (auto it = fs::recursive_directory_iterator(
           input, fs::directory_options::skip_permission_denied, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    if (++seen > maxFiles) break;
    if (bodyPartOf(it->path(), part)) return part;
  }
  return "";
#else
  (void)input, (void)seriesUid, (void)maxFiles;
  return "";
#endif
}

StudyAttributes studyAttributes(const Volume& v, const std::string& input) {
  StudyAttributes a;
  a.modality = v.modality;
  a.seriesDescription = v.study.seriesDescription;
  if (!input.empty() && !v.study.seriesInstanceUid.empty())
    a.bodyPart = seriesBodyPart(input, v.study.seriesInstanceUid);
  return a;
}

}  // namespace voxray
