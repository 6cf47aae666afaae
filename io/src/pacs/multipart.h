#pragma once
// A strict, streaming splitter for multipart/related bodies (RFC 2046 section 5.1, as WADO-RS
// sends them). No Debian-packaged C++ library parses MIME multipart as a stream without
// pulling in a mail framework (GMime: GLib, whole-message parsing), so this is the minimal
// splitter, fuzzed (tests/fuzz). Every departure from the grammar throws Input.
#include <functional>
#include <string>
#include <string_view>

namespace voxray::pacs {

// The boundary parameter of a multipart Content-Type; throws Input when there is none.
std::string multipartBoundary(const std::string& contentType);

// Each part as it streams in: its headers (as sent, lower-cased), its content in pieces as
// they arrive (a series' instances go to disk without being gathered first: a part is held
// back only by the delimiter's length), then its end.
struct PartStream {
  std::function<void(const std::string& headers)> begin;
  std::function<void(std::string_view piece)> content;
  std::function<void()> end;
};

class MultipartSplitter {
 public:
  MultipartSplitter(const std::string& boundary, PartStream stream);
  // ON_PART gets each whole part's headers and content (gathered from the stream).
  using OnPart = std::function<void(const std::string& headers, std::string_view content)>;
  MultipartSplitter(const std::string& boundary, const OnPart& onPart);
  void feed(const char* data, size_t size);
  // Throws Input when the body ended before its close delimiter (truncated).
  void finish();
  int parts() const { return parts_; }

 private:
  void parse();

  enum class State { Preamble, AfterDelimiter, Headers, Content, Done };
  std::string delimiter_;  // "\r\n--" + boundary
  PartStream stream_;
  std::string buffer_;
  size_t scanFrom_ = 0;
  State state_ = State::Preamble;
  std::string headers_;
  int parts_ = 0;
};

}  // namespace voxray::pacs
