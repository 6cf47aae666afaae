#pragma once
// Finding the files of a raw slice stack: a folder of numbered files or a printf pattern.
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace voxray::detail {

struct SliceFile {
  long long number = 0;  // the slice number in the file name
  std::string path;
};
using SliceRange = std::optional<std::pair<int, int>>;

// Every regular file of `folder` whose name ends in a number, or has a number before a short
// extension (001.tif), ordered by that number (not by text: CThead.10 follows CThead.9),
// limited to `range` when given. Of names that end differently (.tif, .txt) the largest
// group is the stack. Throws Error (Input) for an empty folder, two files with one number,
// two groups of one size, or a gap in the numbers.
std::vector<SliceFile> listSliceFolder(const std::string& folder, const SliceRange& range);

// The files named by `pattern` (one %d or %0Nd; %% is a literal %) for every number in
// `range`; without one, from the lowest to the highest number of the files in the pattern's
// folder that it names. Throws Error (Input) for a bad pattern or a missing file.
std::vector<SliceFile> listSlicePattern(const std::string& pattern, const SliceRange& range);

// Number of slices `range` names; throws Error (Input) if first > last or first < 0.
long long sliceCount(const std::pair<int, int>& range);

}  // namespace voxray::detail
