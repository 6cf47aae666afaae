#include "multipart.h"

#include <algorithm>
#include <cctype>

#include "voxray/io/error.h"

namespace voxray::pacs {
namespace {

constexpr size_t kMaxHeaderBytes = 16 << 10;
constexpr size_t kMaxPreambleBytes = 64 << 10;
// Parts from this size on are handed over in the buffer they arrived in (a CT slice is half a
// megabyte); smaller ones are copied out of it. The next buffer gets room for a part as large
// as the last plus kFeedSlack: the feed that ends a part brings the start of the next (curl
// hands over up to 16 KiB at a time).
constexpr size_t kHandOverBytes = 64 << 10;
constexpr size_t kFeedSlack = 64 << 10;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

}  // namespace

std::string multipartBoundary(const std::string& contentType) {
  std::string low = lower(contentType);
  if (low.rfind("multipart/", 0) != 0)
    throw inputError("the server answered with " +
                     (contentType.empty() ? std::string("no content type") : contentType) +
                     ", not multipart/related: it may not be a DICOMweb server");
  size_t at = low.find("boundary=");
  if (at == std::string::npos) throw inputError("the server's multipart answer names no boundary");
  std::string b = contentType.substr(at + 9);
  if (!b.empty() && b[0] == '"') {
    size_t end = b.find('"', 1);
    if (end == std::string::npos) throw inputError("the multipart boundary is not closed by \"");
    b = b.substr(1, end - 1);
  } else {
    b = b.substr(0, b.find_first_of("; \t"));
  }
  if (b.empty() || b.size() > 70) throw inputError("the multipart boundary is empty or too long");
  return b;
}

MultipartSplitter::MultipartSplitter(const std::string& boundary, OnPart onPart,
                                     size_t maxPartBytes)
    : delimiter_("\r\n--" + boundary), onPart_(std::move(onPart)), maxPartBytes_(maxPartBytes) {
  buffer_ = "\r\n";  // the first delimiter may open the body without a CRLF before it
}

void MultipartSplitter::feed(const char* data, size_t size) {
  if (state_ == State::Done) return;  // the epilogue is ignored, as RFC 2046 says
  buffer_.append(data, size);
  parse();
}

void MultipartSplitter::parse() {
  for (;;) {
    if (state_ == State::Preamble || state_ == State::Content) {
      size_t at = buffer_.find(delimiter_, scanFrom_);
      if (at == std::string::npos) {
        if (state_ == State::Preamble && buffer_.size() > kMaxPreambleBytes)
          throw inputError("the multipart body does not start with its boundary");
        // The part's content is all of the buffer but what may start a delimiter.
        if (state_ == State::Content && buffer_.size() + 1 > maxPartBytes_ + delimiter_.size())
          throw partTooLarge();
        scanFrom_ =
            buffer_.size() >= delimiter_.size() ? buffer_.size() - delimiter_.size() + 1 : 0;
        return;
      }
      if (state_ == State::Content) {
        if (at > maxPartBytes_) throw partTooLarge();
        std::string part;
        if (at >= kHandOverBytes) {
          // A large part is the buffer's head: the buffer becomes the part (no copy), and
          // the bytes after it start the next buffer, with room for a part as large.
          part = std::move(buffer_);
          buffer_ = std::string();
          buffer_.reserve(at + kFeedSlack);
          buffer_.assign(part, at + delimiter_.size());
          part.resize(at);
        } else {
          // A small one is copied out: the buffer (and its room) stays for the next.
          part = buffer_.substr(0, at);
          buffer_.erase(0, at + delimiter_.size());
        }
        onPart_(headers_, std::move(part));
        ++parts_;
      } else {
        buffer_.erase(0, at + delimiter_.size());
      }
      scanFrom_ = 0;
      state_ = State::AfterDelimiter;
    } else if (state_ == State::AfterDelimiter) {
      if (buffer_.size() < 2) return;
      if (buffer_.compare(0, 2, "--") == 0) {
        state_ = State::Done;
        buffer_.clear();
        return;
      }
      size_t eol = buffer_.find("\r\n");  // transport padding (spaces) may precede the CRLF
      if (eol == std::string::npos) {
        if (buffer_.size() > 256) throw inputError("a multipart delimiter is not followed by CRLF");
        return;
      }
      if (buffer_.find_first_not_of(" \t") < eol)
        throw inputError("a multipart delimiter is followed by text, not CRLF");
      buffer_.erase(0, eol + 2);
      state_ = State::Headers;
    } else if (state_ == State::Headers) {
      size_t end = buffer_.find("\r\n\r\n");
      if (buffer_.rfind("\r\n", 0) == 0) end = 0;  // a part with no headers
      if (end == std::string::npos) {
        if (buffer_.size() > kMaxHeaderBytes)
          throw inputError("a multipart part's headers are too long");
        return;
      }
      headers_ = lower(buffer_.substr(0, end));
      buffer_.erase(0, end == 0 ? 2 : end + 4);
      scanFrom_ = 0;
      state_ = State::Content;
    } else {
      return;
    }
  }
}

Error MultipartSplitter::partTooLarge() const {
  return inputError("a part of the server's multipart answer is larger than " +
                    (maxPartBytes_ >= (1u << 20) ? std::to_string(maxPartBytes_ >> 20) + " MiB"
                                                 : std::to_string(maxPartBytes_) + " bytes") +
                    ", more than Voxray holds for one image; nothing was kept");
}

void MultipartSplitter::finish() {
  if (state_ != State::Done)
    throw inputError("the multipart body ended before its closing boundary (" +
                     std::to_string(parts_) +
                     " parts complete): the transfer was cut short; try again");
}

}  // namespace voxray::pacs
