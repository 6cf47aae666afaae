#include "bounded_load.h"

#include <dcmtk/dcmdata/dcistrmb.h>
#include <dcmtk/dcmdata/dcistrmf.h>

#include <algorithm>
#include <exception>
#include <memory>
#include <utility>

#include "codec_registry.h"

namespace voxray::dicom {
namespace {

// Every nesting level reads its tags through the stream, so the stream sees the parser's
// stack depth at each level and ends the input once the budget is spent. DCMTK then
// unwinds with a parse error. Measured: about 1.4 KiB of stack per level (a sequence and its
// item; GCC 12, Release), so 2 MiB lets about 1,400 levels through: several times
// kMaxNestingDepth, which leaves room for ASan's larger frames. Threads have 8 MiB.
constexpr std::ptrdiff_t kStackBudget = std::ptrdiff_t(2) << 20;

// STREAM is DCMTK's file or buffer stream.
template <class Stream>
class StackBounded : public Stream {
 public:
  template <class... Args>
  explicit StackBounded(const char* base, Args&&... args)
      : Stream(std::forward<Args>(args)...), base_(base) {}

  bool tooDeep() const { return tooDeep_; }

  OFBool good() const override { return !tooDeep_ && Stream::good(); }
  OFCondition status() const override {
    return tooDeep_ ? EC_SeqOrItemContentOverflow : Stream::status();
  }
  OFBool eos() override { return spent() || Stream::eos(); }
  offile_off_t avail() override { return spent() ? 0 : Stream::avail(); }
  offile_off_t read(void* buf, offile_off_t length) override {
    return spent() ? 0 : Stream::read(buf, length);
  }
  offile_off_t skip(offile_off_t length) override { return spent() ? 0 : Stream::skip(length); }

 private:
  // The stack grows down on every platform Voxray builds for. The frame address, not a
  // local's, because ASan may move locals to a heap-allocated fake stack.
  bool spent() {
    const auto* here = static_cast<const char*>(__builtin_frame_address(0));
    if (base_ - here > kStackBudget) tooDeep_ = true;
    return tooDeep_;
  }

  const char* base_;
  bool tooDeep_ = false;
};

// A file's bytes in memory as a stream that can make factories: DCMTK then leaves long
// values (the pixel data) where they are and reads them from the bytes when first asked,
// as it does from a file, instead of copying each into a value of its own while parsing.
class SharedBytesStream : public DcmInputBufferStream {
 public:
  explicit SharedBytesStream(std::shared_ptr<const std::string> bytes) : bytes_(std::move(bytes)) {
    setBuffer(bytes_->data(), offile_off_t(bytes_->size()));
    setEos();
  }
  DcmInputStreamFactory* newFactory() const override;

 private:
  std::shared_ptr<const std::string> bytes_;
};

class SharedBytesFactory : public DcmInputStreamFactory {
 public:
  SharedBytesFactory(std::shared_ptr<const std::string> bytes, offile_off_t at)
      : bytes_(std::move(bytes)), at_(at) {}
  DcmInputStream* create() const override {
    auto* stream = new SharedBytesStream(bytes_);
    if (stream->skip(at_) != at_) {
      delete stream;
      return nullptr;  // DCMTK reports an invalid stream
    }
    return stream;
  }
  DcmInputStreamFactory* clone() const override { return new SharedBytesFactory(*this); }
  // Not a temporary file: nothing to delete when the value goes.
  DcmInputStreamFactoryType ident() const override { return DFT_DcmInputFileStreamFactory; }

 private:
  std::shared_ptr<const std::string> bytes_;
  offile_off_t at_;
};

DcmInputStreamFactory* SharedBytesStream::newFactory() const {
  return new SharedBytesFactory(bytes_, tell());
}

// Values longer than this stay in the bytes until asked for (as the file readers' callers
// leave them in the file: frame_header.cpp, pixel_decode.cpp).
constexpr Uint32 kLeaveLongValues = 4096;

// The deepest nesting of sequences in DATASET (a sequence in an item of another: 2).
// Walked with DCMTK's own stack, not by recursion.
int sequenceDepth(DcmItem& dataset) {
  DcmStack stack;
  int deepest = 0;
  while (dataset.nextObject(stack, OFTrue).good()) {
    if (stack.top()->ident() != EVR_SQ) continue;  // counted at sequences only
    int depth = 0;
    for (unsigned long i = 0; i < stack.card(); ++i) depth += stack.elem(i)->ident() == EVR_SQ;
    deepest = std::max(deepest, depth);
  }
  return deepest;
}

std::string tooDeepMessage() {
  return "its sequences are nested deeper than Voxray reads (over " +
         std::to_string(kMaxNestingDepth) + " levels)";
}

template <class Stream>
std::string readBounded(DcmFileFormat& file, StackBounded<Stream>& stream, Uint32 maxReadLength,
                        const DcmTagKey& stopAt) {
  if (stream.status().bad())
    return std::string("cannot be opened (") + stream.status().text() + ")";
  file.clear();
  file.transferInit();
  OFCondition status = file.readUntilTag(stream, EXS_Unknown, EGL_noChange, maxReadLength, stopAt);
  file.transferEnd();
  if (stream.tooDeep()) return tooDeepMessage();
  if (status.bad()) return status.text();
  // The stack budget stops far deeper nesting than the limit: the limit itself is counted.
  if (sequenceDepth(*file.getDataset()) > kMaxNestingDepth) return tooDeepMessage();
  return {};
}

}  // namespace

std::string loadDicomFile(DcmFileFormat& file, const std::string& path, Uint32 maxReadLength,
                          const DcmTagKey& stopAt, uint64_t* stoppedAt) {
  ensureCodecsRegistered();
  try {
    StackBounded<DcmInputFileStream> stream(static_cast<const char*>(__builtin_frame_address(0)),
                                            path.c_str());
    std::string why = readBounded(file, stream, maxReadLength, stopAt);
    if (stoppedAt) *stoppedAt = uint64_t(stream.tell());
    return why;
  } catch (const std::exception& e) {
    // DCMTK is C++ and may throw (std::bad_alloc, std::out_of_range) on damaged input.
    file.clear();
    return std::string("the DICOM parser failed (") + e.what() + ")";
  }
}

std::string loadDicomBytes(DcmFileFormat& file, std::shared_ptr<const std::string> bytes) {
  ensureCodecsRegistered();
  try {
    StackBounded<SharedBytesStream> stream(static_cast<const char*>(__builtin_frame_address(0)),
                                           std::move(bytes));
    return readBounded(file, stream, kLeaveLongValues, DCM_UndefinedTagKey);
  } catch (const std::exception& e) {
    file.clear();
    return std::string("the DICOM parser failed (") + e.what() + ")";
  }
}

std::string loadDicomHeader(DcmFileFormat& file, const char* data, size_t size,
                            const DcmTagKey& stopAt) {
  ensureCodecsRegistered();
  try {
    StackBounded<DcmInputBufferStream> stream(static_cast<const char*>(__builtin_frame_address(0)));
    stream.setBuffer(data, offile_off_t(size));
    stream.setEos();
    return readBounded(file, stream, kLeaveLongValues, stopAt);
  } catch (const std::exception& e) {
    file.clear();
    return std::string("the DICOM parser failed (") + e.what() + ")";
  }
}

}  // namespace voxray::dicom
