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
  // Each consumes the head of DATA (SIZE bytes) in its state and returns how many bytes it
  // used: content() the part's content, meta() the rest (preamble, delimiter line, headers).
  size_t content(const char* data, size_t size);
  size_t meta(const char* data, size_t size);
  Error partTooLarge() const;

  enum class State { Preamble, AfterDelimiter, Headers, Content, Done };
  std::string delimiter_;  // "\r\n--" + boundary
  OnPart onPart_;
  // The current part's content, copied once from the fed data (never moved inside): it is
  // handed over as it is. Parts are split in the fed data itself (issue 39 item 8: moving
  // what followed each part to the front of the buffer, twice, copied a CT series again).
  std::string content_;
  std::string meta_;  // what is read of the preamble, a delimiter line or headers
  size_t scanFrom_ = 0;
  size_t lastPart_ = 0;  // the size of the last part: the next one's room
  State state_ = State::Preamble;
  std::string headers_;
  int parts_ = 0;
  size_t maxPartBytes_;
};

}  // namespace voxray::pacs
