#pragma once
// What the study database asks of the files it indexes: their size and modification time
// (an instance changed or gone), and whether a path lies in its own folder.
#include <cstdint>
#include <string>

namespace voxray::studydb {

// Size and modification time of PATH (nanoseconds), following links; false when absent.
bool fileStamp(const std::string& path, uint64_t& size, int64_t& mtime);

// PATH lies under FOLDER (both absolute and normal).
bool isUnder(const std::string& path, const std::string& folder);

}  // namespace voxray::studydb
