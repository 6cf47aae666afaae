#pragma once
// What the hanging protocols match a study by: the volume's modality and series description,
// and the series' Body Part Examined, which the volume reader does not keep, read here from
// the header of one of the series' files.
#include <string>

#include "hanging_protocol.h"
#include "no_qt.h"
#include "voxray/io/volume.h"

namespace voxray {

// Body Part Examined (0018,0015) of the first file under INPUT (a folder or a file) whose
// Series Instance UID is SERIESUID (empty: any), headers only; "" when none says it, INPUT
// is not DICOM or the build has no DICOM. Stops after MAXFILES files: a huge folder costs
// no more than that.
std::string seriesBodyPart(const std::string& input, const std::string& seriesUid,
                           int maxFiles = 2000);

// V's attributes, the body part from INPUT (the folder or file V was read from).
StudyAttributes studyAttributes(const Volume& v, const std::string& input);

}  // namespace voxray
