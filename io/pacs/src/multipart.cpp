#include "multipart.h"

#include <algorithm>
#include <cctype>
#include <string_view>

#include "voxray/io/error.h"

namespace voxray::pacs {
namespace {

constexpr size_t kMaxHeaderBytes = 16 << 10;
constexpr size_t kMaxPreambleBytes = 64 << 10;
// The preamble, delimiter lines and headers are read this much at a time: what follows the
// headers is copied no further than this before it is taken as content.
constexpr size_t kMetaStep = 4 << 10;

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
  meta_ = "\r\n";  // the first delimiter may open the body without a CRLF before it
}

void MultipartSplitter::feed(const char* data, size_t size) {
  // The epilogue (after the close delimiter) is ignored, as RFC 2046 says.
  while (size > 0 && state_ != State::Done) {
    const size_t used = state_ == State::Content ? content(data, size) : meta(data, size);
    data += used;
    size -= used;
  }
}

size_t MultipartSplitter::content(const char* data, size_t size) {
  const size_t d = delimiter_.size();
  size_t end = std::string::npos;  // where the part ends in content_
  size_t used = 0;                 // bytes of DATA up to the end of the delimiter
  // A delimiter that starts in the content held (in its last d - 1 bytes) and ends in DATA.
  const size_t held = std::min(content_.size(), d - 1);
  if (held > 0) {
    std::string edge = content_.substr(content_.size() - held);
    edge.append(data, std::min(size, d - 1));
    const size_t at = edge.find(delimiter_);
    if (at != std::string::npos && at < held) {
      end = content_.size() - held + at;
      used = d - (held - at);
    }
  }
  if (end == std::string::npos) {
    const size_t at = std::string_view(data, size).find(delimiter_);
    if (at == std::string::npos) {
      content_.append(data, size);
      // The part's content is all of it but what may start a delimiter.
      if (content_.size() + 1 > maxPartBytes_ + d) throw partTooLarge();
      return size;
    }
    content_.append(data, at);
    end = content_.size();
    used = at + d;
  }
  if (end > maxPartBytes_) throw partTooLarge();
  // The held content becomes the part (no copy); the next one starts in a buffer of its own.
  std::string part = std::move(content_);
  content_ = std::string();
  part.resize(end);
  lastPart_ = end;
  state_ = State::AfterDelimiter;
  onPart_(headers_, std::move(part));
  ++parts_;
  return used;
}

size_t MultipartSplitter::meta(const char* data, size_t size) {
  const size_t before = meta_.size();
  const size_t take = std::min(size, kMetaStep);
  meta_.append(data, take);
  size_t end = 0;  // bytes of meta_ this state takes; what follows is the next state's
  if (state_ == State::Preamble) {
    const size_t at = meta_.find(delimiter_, scanFrom_);
    if (at == std::string::npos) {
      if (meta_.size() > kMaxPreambleBytes)
        throw inputError("the multipart body does not start with its boundary");
      scanFrom_ = meta_.size() >= delimiter_.size() ? meta_.size() - delimiter_.size() + 1 : 0;
      return take;
    }
    end = at + delimiter_.size();
    state_ = State::AfterDelimiter;
  } else if (state_ == State::AfterDelimiter) {
    if (meta_.size() < 2) return take;
    if (meta_.compare(0, 2, "--") == 0) {
      state_ = State::Done;
      meta_.clear();
      return size;
    }
    const size_t eol = meta_.find("\r\n");  // transport padding (spaces) may precede the CRLF
    if (eol == std::string::npos) {
      if (meta_.size() > 256) throw inputError("a multipart delimiter is not followed by CRLF");
      return take;
    }
    if (meta_.find_first_not_of(" \t") < eol)
      throw inputError("a multipart delimiter is followed by text, not CRLF");
    end = eol + 2;
    state_ = State::Headers;
  } else {  // Headers
    if (meta_.rfind("\r\n", 0) == 0) {
      headers_.clear();  // a part with no headers
      end = 2;
    } else {
      const size_t at = meta_.find("\r\n\r\n");
      if (at == std::string::npos) {
        if (meta_.size() > kMaxHeaderBytes)
          throw inputError("a multipart part's headers are too long");
        return take;
      }
      headers_ = lower(meta_.substr(0, at));
      end = at + 4;
    }
    state_ = State::Content;
    // Room for a part as large as the last (a series' images are alike) and a delimiter's
    // start: the content is appended without reallocating.
    content_.reserve(lastPart_ + delimiter_.size());
  }
  meta_.clear();
  scanFrom_ = 0;
  return end - before;  // the rest of DATA is read again in the next state
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
