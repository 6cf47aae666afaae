#pragma once
// A NRRD header read as text before Teem parses it (issue 39). Teem's parser takes time
// quadratic in the header's lines (each key/value pair is compared with every earlier one),
// counts a data-file range that reaches INT_MAX for ever, formats a data-file pattern into a
// buffer sized for 10 more characters than the pattern, and opens detached data files wherever
// they point, standard input ("-") included; it opens them even when only the header is read.
#include <cstdint>
#include <string>
#include <vector>

namespace voxray::formats {

inline constexpr size_t kMaxNrrdHeaderLines = 4096;      // fields, comments, key/value pairs
inline constexpr size_t kMaxNrrdHeaderBytes = 1u << 20;  // the header and its file list
inline constexpr size_t kMaxNrrdDataFiles = 8192;        // Teem walks the list once per file
// A field line (or a data file's name) Teem may quote in an error message, which it formats
// into a buffer of 1 KiB: a line of about 1,000 characters that it cannot parse overflowed it
// (found by the volume_file fuzz target). Comments and key/value pairs may be longer.
inline constexpr size_t kMaxNrrdFieldLineBytes = 512;

struct NrrdDataFiles {
  // The "data file" field as Teem keeps it: the names of a single file or a list, or a pattern
  // (FORMAT with one %d, FIRST, LAST, STEP). Both empty: the data follow the header.
  std::vector<std::string> names;
  std::string format;
  int first = 0, last = 0, step = 1;
  struct File {
    std::string name;      // as the header gives it (a pattern's formatted)
    std::string resolved;  // links resolved: what Teem will open
  };
  std::vector<File> files;  // in reading order
};

// Throws Error (Input) for a header over the limits above (a field line over 512 bytes too), a
// pattern that is not one integer conversion of a sane width over a range bounded by the sizes,
// more files than the sizes allow, or a data file that is missing, not a regular file or outside
// the header's folder once links are resolved.
NrrdDataFiles checkNrrdHeader(const std::string& path);

// After Teem read the header: each raw data file holds BYTES_PER_FILE bytes (exactly, or at
// least that many when SKIPS says the header skips lines or bytes). Throws Error (Input).
void checkNrrdDataFileSizes(const NrrdDataFiles& d, uint64_t bytesPerFile, bool skips,
                            const std::string& path);

}  // namespace voxray::formats
