#pragma once
// What Voxray needs to know about one image (one frame of a file), read from headers only.
// Enhanced multi-frame files give one FrameHeader per frame, with per-frame geometry.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/io/suv.h"
#include "voxray/io/volume.h"

class DcmFileFormat;

namespace voxray::dicom {

struct FrameHeader {
  std::string path;
  int frame = 0;       // index inside the file
  int fileFrames = 1;  // NumberOfFrames of the file
  std::string seriesUid, sopClassUid, sopInstanceUid, modality, description, imageType, photometric;
  std::string transferSyntaxUid;
  int seriesNumber = 0, instanceNumber = 0, acquisitionNumber = 0;
  int temporalIndex = 0;  // TemporalPositionIndex / DimensionIndexValues, 0 when absent
  int stackId = 0;
  double triggerTime = 0.0;  // TriggerTime (ms): orders cardiac phases at one position
  std::string acquisitionDate, acquisitionTime;  // of this image; PET's scan time
  // PET only (Modality PT): what SUV needs, read from the file's first frame.
  std::shared_ptr<const PetSuvAttributes> pet;
  int rows = 0, columns = 0, samplesPerPixel = 1;
  int planarConfiguration = 0;  // colour: 0 = RGBRGB..., 1 = RR..GG..BB..
  int bitsAllocated = 16, bitsStored = 16, pixelRepresentation = 0;
  bool hasPosition = false, hasOrientation = false, hasPixelSpacing = false;
  glm::dvec3 position{0.0};
  glm::dvec3 rowDir{1, 0, 0};    // direction of increasing column index (i)
  glm::dvec3 colDir{0, 1, 0};    // direction of increasing row index (j)
  glm::dvec2 pixelSpacing{1.0};  // x: between columns (i), y: between rows (j)
  double sliceThickness = 0.0, spacingBetweenSlices = 0.0;
  double gantryTilt = 0.0;
  double slope = 1.0, intercept = 0.0;
  std::optional<int32_t> padding, paddingLimit;  // stored values meaning "no data"
  std::optional<DisplayWindow> window;           // the first WindowCenter/Width pair
  // Display only; never logged or put in messages.
  std::string patientName, patientId, patientBirthDate;
  std::string studyUid, studyDate, studyTime, studyDescription, studyId, accession,
      frameOfReferenceUid;

  glm::dvec3 normal() const { return glm::normalize(glm::cross(rowDir, colDir)); }
  bool isEnhanced() const { return fileFrames > 1 || perFrameGroups; }
  bool perFrameGroups = false;
  // Where the header scan of the file stopped: just after the pixel data's tag, VR and length
  // when the file has its pixel data at the top level (NativeFrames checks before using it);
  // 0 when read from bytes or unknown.
  uint64_t pixelValueOffset = 0;
  // A tile of a Siemens mosaic (siemens_mosaic.h): rows, columns and position above are the
  // tile's; the pixels are cut from frame `frame` of ROWS x COLUMNS.
  struct MosaicTile {
    int tile = 0, images = 0, across = 0, rows = 0, columns = 0;
  };
  std::optional<MosaicTile> mosaic;
  // Which image of the file this is, counting each mosaic tile: frame, or frame * images + tile.
  int imageIndex() const { return mosaic ? frame * mosaic->images + mosaic->tile : frame; }
};

enum class ScanResult { Image, NotDicom, NoImage };

// Reads the headers of PATH (pixel data is not loaded). Appends one FrameHeader per
// frame to OUT. WHY says, for NotDicom/NoImage, what the file was.
ScanResult readFrameHeaders(const std::string& path, std::vector<FrameHeader>& out,
                            std::string& why);
// The same for the whole file's BYTES in memory (what would be at PATH), parsed into FILE,
// so its pixels can be decoded without reading it again: FILE reads its pixel data from
// BYTES, which it keeps alive.
ScanResult readFrameHeaders(const std::string& path, std::shared_ptr<const std::string> bytes,
                            DcmFileFormat& file, std::vector<FrameHeader>& out, std::string& why);

// Human name of a transfer syntax UID ("JPEG 2000 lossless", ...), or the UID itself.
std::string transferSyntaxName(const std::string& uid);

}  // namespace voxray::dicom
