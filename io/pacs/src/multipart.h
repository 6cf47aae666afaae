#pragma once
// A strict, streaming splitter for multipart/related bodies (RFC 2046 section 5.1, as WADO-RS
// sends them). No Debian-packaged C++ library parses MIME multipart as a stream without
// pulling in a mail framework (GMime: GLib, whole-message parsing), so this is the minimal
// splitter, fuzzed (tests/fuzz). Every departure from the grammar throws Input.
#include <functional>
#include <string>

#include "voxray/io/error.h"

namespace voxray::pacs {

// The boundary parameter of a multipart Content-Type; throws Input when there is none.
std::string multipartBoundary(const std::string& contentType);

// The largest part kept: one DICOM instance held in memory until it is complete (an
// enhanced multi-frame series of 2,000 CT slices is about 1 GiB).
constexpr size_t kMaxPartBytes = size_t(2) << 30;

class MultipartSplitter {
 public:
  // ON_PART gets each part's headers (as sent, lower-cased names) and its content, which it
  // may keep (handed over, not copied: a part of a CT series is half a megabyte).
  using OnPart = std::function<void(const std::string& headers, std::string content)>;
  // A part larger than MAX_PART_BYTES throws Input.
  MultipartSplitter(const std::string& boundary, OnPart onPart,
                    size_t maxPartBytes = kMaxPartBytes);
  void feed(const char* data, size_t size);
  // Throws Input when the body ended before its close delimiter (truncated).
  void finish();
  int parts() const { return parts_; }

 private:
  void parse();
  Error partTooLarge() const;

  enum class State { Preamble, AfterDelimiter, Headers, Content, Done };
  std::string delimiter_;  // "\r\n--" + boundary
  OnPart onPart_;
  std::string buffer_;
  size_t scanFrom_ = 0;
  State state_ = State::Preamble;
  std::string headers_;
  int parts_ = 0;
  size_t maxPartBytes_;
};

}  // namespace voxray::pacs
