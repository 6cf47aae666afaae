#include "pixel_decode.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dccodec.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfcache.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcpixel.h>
#include <dcmtk/dcmdata/dcpixseq.h>
#include <dcmtk/dcmdata/dcpxitem.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>

#include "bounded_load.h"
#include "j2k_decode.h"
#include "voxray/io/error.h"

namespace voxray::dicom {
namespace {

bool isJpeg2000(E_TransferSyntax x) {
  return x == EXS_JPEG2000LosslessOnly || x == EXS_JPEG2000 ||
         x == EXS_JPEG2000MulticomponentLosslessOnly || x == EXS_JPEG2000Multicomponent;
}

// Masks to BitsStored and sign-extends, so 12-bit signed data and junk in the unused high
// bits both come out right.
struct SampleFormat {
  int bits;
  bool isSigned;
  int32_t operator()(uint32_t raw) const {
    uint32_t v = bits >= 32 ? raw : raw & ((1u << bits) - 1u);
    if (isSigned && bits < 32 && (v >> (bits - 1)) & 1u) return int32_t(v) - int32_t(1u << bits);
    return int32_t(v);
  }
};

// Fragments [first, last) of FRAME in an encapsulated pixel sequence (item 0 is the
// offset table).
void fragmentRange(DcmPixelSequence* seq, int frame, int frames, Uint32& first, Uint32& last) {
  Uint32 count = Uint32(seq->card());
  if (frames <= 1) {
    first = 1;
    last = count;
    return;
  }
  if (DcmCodec::determineStartFragment(Uint32(frame), frames, seq, first).bad()) first = 0;
  Uint32 next = count;
  if (frame + 1 < frames &&
      DcmCodec::determineStartFragment(Uint32(frame + 1), frames, seq, next).bad())
    next = 0;
  if (first == 0 || next == 0) {
    // No usable offset table: a JPEG 2000 codestream starts with SOC + SIZ (FF4F FF51).
    std::vector<Uint32> starts;
    for (Uint32 i = 1; i < count; ++i) {
      DcmPixelItem* item = nullptr;
      Uint8* bytes = nullptr;
      if (seq->getItem(item, i).good() && item->getLength() >= 4 &&
          item->getUint8Array(bytes).good() && bytes && bytes[0] == 0xFF && bytes[1] == 0x4F)
        starts.push_back(i);
    }
    if (size_t(frame) >= starts.size())
      throw inputError("frame " + std::to_string(frame + 1) + " has no JPEG 2000 data");
    first = starts[size_t(frame)];
    next = size_t(frame) + 1 < starts.size() ? starts[size_t(frame) + 1] : count;
  }
  last = std::min(next, count);
  if (first < 1 || first >= last)
    throw inputError("frame " + std::to_string(frame + 1) + " has no compressed data");
}

}  // namespace

struct PixelFile::Impl {
  std::string path;
  std::unique_ptr<DcmFileFormat> file = std::make_unique<DcmFileFormat>();
  DcmDataset* ds = nullptr;
  DcmPixelData* pixels = nullptr;
  E_TransferSyntax xfer = EXS_Unknown;
  std::vector<uint8_t> buffer;  // one decoded or concatenated frame
  int lastFrame = -2;
  Uint32 nextStart = 0;
  int mosaicFrame = -1;  // the frame whose whole mosaic is in mosaicValues
  std::vector<int32_t> mosaicValues;

  [[noreturn]] void fail(const std::string& why) const { throw inputError(path + ": " + why); }

  void decodeJ2k(const FrameHeader& h, std::vector<int32_t>& out) {
    DcmPixelSequence* seq = nullptr;
    if (pixels->getEncapsulatedRepresentation(xfer, nullptr, seq).bad() || !seq)
      fail("the JPEG 2000 pixel data is missing or damaged");
    Uint32 first = 0, last = 0;
    fragmentRange(seq, h.frame, h.fileFrames, first, last);
    buffer.clear();
    for (Uint32 i = first; i < last; ++i) {
      DcmPixelItem* item = nullptr;
      Uint8* bytes = nullptr;
      if (seq->getItem(item, i).bad() || item->getUint8Array(bytes).bad()) continue;
      if (bytes) buffer.insert(buffer.end(), bytes, bytes + item->getLength());
    }
    J2kImage img;
    try {
      img = decodeJpeg2000(buffer.data(), buffer.size());
    } catch (const Error& e) {
      fail(std::string(e.what()) + " (frame " + std::to_string(h.frame + 1) + ")");
    }
    if (img.width != h.columns || img.height != h.rows)
      fail("the JPEG 2000 image is " + std::to_string(img.width) + "x" +
           std::to_string(img.height) + " but the header says " + std::to_string(h.columns) + "x" +
           std::to_string(h.rows));
    SampleFormat fmt{std::clamp(h.bitsStored, 1, 32), h.pixelRepresentation == 1};
    out.resize(img.samples.size());
    for (size_t i = 0; i < out.size(); ++i) out[i] = fmt(uint32_t(img.samples[i]));
  }

  void decodeOther(const FrameHeader& h, std::vector<int32_t>& out) {
    const size_t n = size_t(h.rows) * size_t(h.columns);
    const size_t bytesPerSample = size_t(h.bitsAllocated) / 8;
    const size_t frameBytes = n * size_t(h.samplesPerPixel) * bytesPerSample;
    SampleFormat fmt{std::clamp(h.bitsStored, 1, h.bitsAllocated), h.pixelRepresentation == 1};
    const uint8_t* src = nullptr;
    if (DcmXfer(xfer).isEncapsulated()) {
      if (!DcmCodecList::canChangeCoding(xfer, EXS_LittleEndianExplicit))
        fail("transfer syntax " + transferSyntaxName(DcmXfer(xfer).getXferID()) +
             " is not supported; convert the study with a DICOM tool (e.g. dcmdjpeg)");
      buffer.assign(frameBytes + (frameBytes & 1), 0);
      // DCMTK finds the first fragment itself (0) and tells where the next frame starts,
      // which is exact when frames are read in order.
      Uint32 start = h.frame == lastFrame + 1 ? nextStart : 0;
      OFString colourModel;
      OFCondition c = pixels->getUncompressedFrame(ds, Uint32(h.frame), start, buffer.data(),
                                                   Uint32(buffer.size()), colourModel);
      lastFrame = h.frame;
      nextStart = start;
      if (c.bad())
        fail(std::string("frame ") + std::to_string(h.frame + 1) + " cannot be decoded (" +
             c.text() + "); the compressed data is damaged");
      src = buffer.data();
    } else {
      const size_t offset = size_t(h.frame) * frameBytes;
      Uint8* bytes = nullptr;
      Uint16* words = nullptr;
      size_t available = 0;
      if (bytesPerSample == 1 && pixels->getUint8Array(bytes).good() && bytes) {
        src = bytes;
        available = pixels->getLength();
      } else if (bytesPerSample == 2 && pixels->getUint16Array(words).good() && words) {
        src = reinterpret_cast<const uint8_t*>(words);  // already in local byte order
        available = pixels->getLength();
      }
      if (!src || available < offset + frameBytes)
        fail("the pixel data is shorter than " + std::to_string(h.columns) + "x" +
             std::to_string(h.rows) + "x" + std::to_string(h.fileFrames) +
             " samples; the file is truncated");
      src += offset;
    }
    out.resize(n);
    const size_t step = size_t(h.samplesPerPixel);
    if (isLuminanceRgb(h)) {
      // Rec. 601 luma, the greyscale a colour screenshot is shown as (rounded, 0-255).
      const size_t plane = h.planarConfiguration == 1 ? n : 1;
      const size_t pixel = h.planarConfiguration == 1 ? 1 : 3;
      for (size_t i = 0; i < n; ++i) {
        const uint8_t* p = src + i * pixel;
        out[i] = int32_t((299 * p[0] + 587 * p[plane] + 114 * p[2 * plane] + 500) / 1000);
      }
    } else if (bytesPerSample == 1) {
      for (size_t i = 0; i < n; ++i) out[i] = fmt(src[i * step]);
    } else if (step == 1 && fmt.bits == 16) {
      // The common case, without masking: a straight (vectorised) widening copy.
      if (fmt.isSigned) {
        const auto* s16 = reinterpret_cast<const int16_t*>(src);
        for (size_t i = 0; i < n; ++i) out[i] = s16[i];
      } else {
        const auto* u16 = reinterpret_cast<const uint16_t*>(src);
        for (size_t i = 0; i < n; ++i) out[i] = u16[i];
      }
    } else {
      for (size_t i = 0; i < n; ++i) {
        uint16_t v;
        std::memcpy(&v, src + 2 * i * step, 2);
        out[i] = fmt(v);
      }
    }
  }
};

PixelFile::PixelFile(const std::string& path) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  if (std::string why = loadDicomFile(*impl_->file, path, DCM_MaxReadLength); !why.empty())
    impl_->fail("cannot be read (" + why +
                "); the file is damaged or incomplete: copy it again or remove it");
  findPixels();
}

PixelFile::PixelFile(const std::string& path, std::unique_ptr<DcmFileFormat> loaded)
    : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  impl_->file = std::move(loaded);
  findPixels();
}

void PixelFile::findPixels() {
  impl_->ds = impl_->file->getDataset();
  impl_->xfer = impl_->ds->getOriginalXfer();
  DcmElement* element = nullptr;
  if (impl_->ds->findAndGetElement(DCM_PixelData, element).bad() || !element)
    impl_->fail("has no pixel data");
  impl_->pixels = dynamic_cast<DcmPixelData*>(element);
  if (!impl_->pixels) impl_->fail("the pixel data element is damaged");
}

PixelFile::~PixelFile() = default;

void PixelFile::frameValues(const FrameHeader& h, std::vector<int32_t>& out) {
  if (std::string why = unsupportedReason(h); !why.empty()) impl_->fail(why);
  if (!h.mosaic) {
    if (isJpeg2000(impl_->xfer))
      impl_->decodeJ2k(h, out);
    else
      impl_->decodeOther(h, out);
    return;
  }
  // A mosaic tile: the whole image is decoded once for all of its tiles.
  const FrameHeader::MosaicTile& m = *h.mosaic;
  if (impl_->mosaicFrame != h.frame) {
    FrameHeader whole = h;
    whole.mosaic.reset();
    whole.rows = m.rows;
    whole.columns = m.columns;
    impl_->mosaicFrame = -1;
    frameValues(whole, impl_->mosaicValues);
    impl_->mosaicFrame = h.frame;
  }
  const size_t across = size_t(m.across), tileRows = size_t(h.rows), tileCols = size_t(h.columns);
  const size_t row0 = size_t(m.tile) / across * tileRows, col0 = size_t(m.tile) % across * tileCols;
  out.resize(tileRows * tileCols);
  for (size_t j = 0; j < tileRows; ++j)
    std::copy_n(impl_->mosaicValues.begin() + ptrdiff_t((row0 + j) * size_t(m.columns) + col0),
                tileCols, out.begin() + ptrdiff_t(j * tileCols));
}

namespace {

// The frame's 16-bit words, sample for sample, as they lie in an uncompressed
// little-endian file; the other checks (bit depth, colour) are the header's.
bool nativeWords(const FrameHeader& h) {
  return gLocalByteOrder == EBO_LittleEndian && h.bitsAllocated == 16 && h.samplesPerPixel == 1 &&
         unsupportedReason(h).empty();
}

// The file's pixel data value where the header scan stopped (h.pixelValueOffset), found
// without parsing the file again: the tag, VR and length just before that offset must say
// "pixel data, OW (or implicit), this many bytes", and the value must lie inside the file.
class DirectPixels {
 public:
  explicit DirectPixels(const std::string& path) : path_(path) {}
  ~DirectPixels() {
    if (fd_ >= 0) ::close(fd_);
  }
  DirectPixels(const DirectPixels&) = delete;
  DirectPixels& operator=(const DirectPixels&) = delete;

  bool read(const FrameHeader& h, uint16_t* out) {
    const uint64_t frameBytes = uint64_t(h.rows) * uint64_t(h.columns) * 2;
    if (!find(h) || uint64_t(h.frame + 1) * frameBytes > length_) return false;
    auto* to = reinterpret_cast<char*>(out);
    uint64_t at = offset_ + uint64_t(h.frame) * frameBytes, left = frameBytes;
    while (left > 0) {
      const ssize_t n = ::pread(fd_, to, size_t(left), off_t(at));
      if (n <= 0) return false;  // the file shrank since the scan: the general path says so
      to += n, at += uint64_t(n), left -= uint64_t(n);
    }
    return true;
  }

 private:
  bool find(const FrameHeader& h) {
    if (tried_) return fd_ >= 0;
    tried_ = true;
    const bool explicitVr = h.transferSyntaxUid == UID_LittleEndianExplicitTransferSyntax;
    const bool implicitVr = h.transferSyntaxUid == UID_LittleEndianImplicitTransferSyntax;
    const uint64_t head = explicitVr ? 12 : 8;
    if ((!explicitVr && !implicitVr) || h.pixelValueOffset < head) return false;
    const int fd = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    unsigned char b[12];
    struct stat st {};
    const off_t tagAt = off_t(h.pixelValueOffset - head);
    bool ok = ::fstat(fd, &st) == 0 && ::pread(fd, b, size_t(head), tagAt) == ssize_t(head) &&
              b[0] == 0xe0 && b[1] == 0x7f && b[2] == 0x10 && b[3] == 0x00 &&
              (!explicitVr || (b[4] == 'O' && b[5] == 'W' && b[6] == 0 && b[7] == 0));
    if (ok) {
      const unsigned char* len = b + head - 4;
      length_ = uint64_t(len[0]) | uint64_t(len[1]) << 8 | uint64_t(len[2]) << 16 |
                uint64_t(len[3]) << 24;
      offset_ = h.pixelValueOffset;
      ok = length_ != 0xffffffffu && offset_ + length_ <= uint64_t(st.st_size);
    }
    if (!ok) {
      ::close(fd);
      return false;
    }
    fd_ = fd;
    return true;
  }

  std::string path_;
  int fd_ = -1;
  bool tried_ = false;
  uint64_t offset_ = 0, length_ = 0;
};

}  // namespace

struct NativeFrames::Impl {
  std::string path;
  std::unique_ptr<DirectPixels> direct;  // files read from a path
  std::unique_ptr<DcmFileFormat> own;    // parsed when the direct read cannot be used
  bool parsed = false;                   // find() ran (on OWN or on the caller's parse)
  DcmPixelData* pixels = nullptr;
  DcmFileCache cache;  // one open file for every frame

  void find(DcmFileFormat& file) {
    parsed = true;
    DcmDataset* ds = file.getDataset();
    const E_TransferSyntax xfer = ds->getOriginalXfer();
    if (xfer != EXS_LittleEndianExplicit && xfer != EXS_LittleEndianImplicit) return;
    DcmElement* element = nullptr;
    if (ds->findAndGetElement(DCM_PixelData, element).bad() || !element) return;
    pixels = dynamic_cast<DcmPixelData*>(element);
  }
  // Parses the file at PATH once, when first needed.
  void parse() {
    if (parsed) return;
    parsed = true;
    own = std::make_unique<DcmFileFormat>();
    // Values over 4 KiB stay in the file until read: the pixel data is read by frame below.
    if (loadDicomFile(*own, path, 4096).empty()) find(*own);
  }
};

NativeFrames::NativeFrames(const std::string& path) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  impl_->direct = std::make_unique<DirectPixels>(path);
}

NativeFrames::NativeFrames(DcmFileFormat& parsed) : impl_(std::make_unique<Impl>()) {
  impl_->find(parsed);
}

NativeFrames::~NativeFrames() = default;

bool NativeFrames::fits(const FrameHeader& h) const {
  if (h.mosaic) return false;  // a tile's rows are not contiguous: PixelFile cuts them out
  impl_->parse();
  const size_t frameBytes = size_t(h.rows) * size_t(h.columns) * 2;
  return impl_->pixels && nativeWords(h) &&
         (impl_->pixels->getVR() == EVR_OW || impl_->pixels->getVR() == EVR_ox) &&
         size_t(h.frame + 1) * frameBytes <= impl_->pixels->getLength();
}

bool NativeFrames::read(const FrameHeader& h, uint16_t* out) {
  if (h.mosaic) return false;
  if (impl_->direct && nativeWords(h) && impl_->direct->read(h, out)) return true;
  if (!fits(h)) return false;
  const size_t frameBytes = size_t(h.rows) * size_t(h.columns) * 2;
  return impl_->pixels
      ->getPartialValue(out, Uint32(size_t(h.frame) * frameBytes), Uint32(frameBytes),
                        &impl_->cache, gLocalByteOrder)
      .good();
}

bool isLuminanceRgb(const FrameHeader& h) {
  return h.samplesPerPixel == 3 && h.photometric == "RGB" && h.bitsAllocated == 8 &&
         !DcmXfer(h.transferSyntaxUid.c_str()).isEncapsulated();
}

std::string unsupportedReason(const FrameHeader& h) {
  if (isLuminanceRgb(h)) return {};
  const bool monochrome = h.photometric == "MONOCHROME1" || h.photometric == "MONOCHROME2";
  if (monochrome && h.samplesPerPixel != 1)
    return "says " + h.photometric + " (greyscale) but has " + std::to_string(h.samplesPerPixel) +
           " samples per pixel; the file is inconsistent";
  if (h.samplesPerPixel != 1 || (!monochrome && !h.photometric.empty()))
    return "is a colour image (" + (h.photometric.empty() ? "RGB" : h.photometric) +
           "); Voxray renders greyscale CT/MR volumes only";
  if (h.bitsAllocated != 8 && h.bitsAllocated != 16)
    return "has " + std::to_string(h.bitsAllocated) +
           "-bit samples; only 8- and 16-bit greyscale images are supported";
  if (h.rows <= 0 || h.columns <= 0 || h.rows > 16384 || h.columns > 16384)
    return "has an implausible image size " + std::to_string(h.columns) + "x" +
           std::to_string(h.rows);
  return {};
}

}  // namespace voxray::dicom
