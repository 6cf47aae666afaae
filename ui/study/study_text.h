#pragma once
// The patient and study corner text a viewer may show (DICOM viewers' "overlay text"):
// off by default, and never in exports unless the user ticks it, because it identifies
// the patient.
#include <string>
#include <vector>

#include "no_qt.h"
#include "voxray/io/volume.h"

namespace voxray {

// Lines for a view's corner, empty fields left out: the patient ("FAMILY, Given"), the
// patient ID and birth date, the study date and time with its description, the accession
// number, and the series number with its description. Empty for a volume without a study
// (raw data, the phantom).
std::vector<std::string> studyTextLines(const StudyIdentity& study);

// A DICOM person name (PS3.5 6.2: Family^Given^Middle^Prefix^Suffix, "=" before the
// ideographic and phonetic forms) as "FAMILY, Given Middle"; the first form only.
std::string displayPersonName(const std::string& dicomName);

// A DICOM DA (YYYYMMDD) as YYYY-MM-DD, with TM (HHMMSS.frac) as " HH:MM" when given; any
// other text is returned as it is.
std::string displayDate(const std::string& da, const std::string& tm = {});

}  // namespace voxray
