#pragma once
// Pixel access for one file: native, DCMTK-decoded (JPEG, JPEG-LS, RLE, deflate) and
// OpenJPEG-decoded (JPEG 2000) frames, as exact stored values (no windowing, no LUTs).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "frame_header.h"

class DcmFileFormat;

namespace voxray::dicom {

class PixelFile {
 public:
  // Loads the whole file. Throws Error (Input) naming PATH when it is damaged.
  explicit PixelFile(const std::string& path);
  // A file already parsed in full (readFrameHeaders from its bytes); PATH names it in errors.
  PixelFile(const std::string& path, std::unique_ptr<DcmFileFormat> loaded);
  ~PixelFile();
  PixelFile(const PixelFile&) = delete;
  PixelFile& operator=(const PixelFile&) = delete;

  // Stored values of frame H.frame (columns x rows), masked to BitsStored and sign-extended
  // when PixelRepresentation is 1. Throws Error (Input) naming the file and the reason.
  void frameValues(const FrameHeader& h, std::vector<int32_t>& out);

 private:
  void findPixels();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The frames of an uncompressed little-endian 16-bit greyscale file, read from the file
// straight into the caller's memory: the common CT/MR file skips DCMTK's copy of its pixel
// data and the 32-bit widening of PixelFile. From a path, the frames are read at the offset
// where the header scan stopped (FrameHeader::pixelValueOffset) once the bytes before it are
// checked, without parsing the file again; otherwise the file is parsed here. For anything
// else, or on any failure, the answer is false and the caller uses PixelFile, which reports
// the error as it always has.
class NativeFrames {
 public:
  explicit NativeFrames(const std::string& path);
  // A file already parsed in full (readFrameHeaders from its bytes); PARSED must outlive this.
  explicit NativeFrames(DcmFileFormat& parsed);
  ~NativeFrames();
  NativeFrames(const NativeFrames&) = delete;
  NativeFrames& operator=(const NativeFrames&) = delete;

  // Whether frame H can be read here (the file parsed, H describes such a file, and its
  // pixel data holds the frame).
  bool fits(const FrameHeader& h) const;
  // The stored 16-bit words of frame H.frame, unmasked, into OUT (columns x rows).
  bool read(const FrameHeader& h, uint16_t* out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Uncompressed 8-bit RGB (a Secondary Capture, such as Voxray's own screenshots): loaded
// as its luminance, with a warning. Compressed colour stays refused.
bool isLuminanceRgb(const FrameHeader& h);
// Empty when frames with this header can be decoded; otherwise why not, naming the cause.
std::string unsupportedReason(const FrameHeader& h);

}  // namespace voxray::dicom
