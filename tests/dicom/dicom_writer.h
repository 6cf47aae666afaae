#pragma once
// Small DICOM files written by the tests themselves (DCMTK), for the cases the shared data
// does not have: text in other character sets, hostile structure.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace voxray::test {

struct TestSlice {
  std::string charset;      // SpecificCharacterSet; empty: none (the default repertoire)
  std::string description;  // SeriesDescription, raw bytes in CHARSET
  std::string patientName;  // PatientName, raw bytes in CHARSET
  std::string modality = "CT";
  int size = 4;            // Rows = Columns
  int numberOfFrames = 0;  // > 0: NumberOfFrames says this (one frame of pixels is stored)
  double z = 0.0;          // ImagePositionPatient z in mm
  // When set: the whole ImagePositionPatient, ImageOrientationPatient (row, column
  // directions), PixelSpacing, and pixel (column, row)'s value; they replace z and i - 8.
  std::optional<std::array<double, 3>> position;
  std::array<double, 6> orientation{1, 0, 0, 0, 1, 0};
  double pixelSpacing = 1.0;
  std::function<int16_t(int column, int row)> pixel;
  int instance = 1;
  std::string seriesUid = "1.2.826.0.1.3680043.10.1082.1";
  // The stored sample format, and pixel i's word: i - 8 (as int16), or with ALL_WORDS
  // (SIZE 256) word i XOR WORD_XOR, every 16-bit pattern once.
  int bitsStored = 16, pixelRepresentation = 1;
  int samplesPerPixel = 1;
  std::string photometric = "MONOCHROME2";
  std::optional<int> padding, paddingLimit;  // PixelPaddingValue / RangeLimit (US or SS)
  bool allWords = false;
  uint16_t wordXor = 0;
  bool deflated = false;         // Deflated Explicit VR Little Endian instead of Explicit VR LE
  bool implicitVr = false;       // Implicit VR Little Endian instead
  bool trailingPadding = false;  // DataSetTrailingPadding after the pixel data
};

// A SIZE x SIZE CT image (by default int16, pixel i = i - 8) in explicit VR little endian.
// Throws std::runtime_error when DCMTK cannot write it.
void writeTestSlice(const std::string& path, const TestSlice& slice);

// Rewrites PATH with sequences nested DEPTH deep (each an undefined-length
// ReferencedImageSequence holding one item) at the start of its dataset, closed properly.
void nestSequences(const std::string& path, int depth);

// A DICOMDIR (Media Storage Directory) at PATH with one IMAGE record per REFERENCED_FILE_IDS
// entry, each written as given ("IMG\\1.dcm"): hostile ones too, which DCMTK's own DICOMDIR
// builder would refuse. Throws std::runtime_error when DCMTK cannot write it.
void writeDicomDir(const std::string& path, const std::vector<std::string>& referencedFileIds);

// Rewrites the length field of PixelData in PATH (written by writeTestSlice) to LENGTH.
void setPixelDataLength(const std::string& path, uint32_t length);

}  // namespace voxray::test
