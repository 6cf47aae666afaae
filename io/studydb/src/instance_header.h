#pragma once
// One file's contribution to the database, read with DCMTK from its headers only: the parse
// stops at the pixel data, so a 500 KB CT slice costs a few kilobytes of reading.
#include <string>

#include "voxray/studydb/study_records.h"

namespace voxray::studydb {

enum class HeaderResult { Instance, NotDicom, Skipped };

// Fills OUT (all but instance.path, size, mtime and stored). WHY says, when the file is not
// an instance, what it is or what is wrong (no patient data).
HeaderResult readInstanceHeader(const std::string& path, InstanceRecord& out, std::string& why);

}  // namespace voxray::studydb
