#pragma once
// Siemens mosaics (fMRI, DWI): the slices of one volume tiled in one image. Split as dcm2niix
// splits them: NumberOfImagesInMosaic slices in a ceil(sqrt(N)) x ceil(sqrt(N)) grid of
// tiles, the first tile's position moved from the whole image's corner to its own, the
// others along the slice normal.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "frame_header.h"

class DcmItem;

namespace voxray::dicom {

// What the mosaic split needs from the SIEMENS CSA HEADER's image header (0029,xx10).
struct CsaImageInfo {
  std::optional<int> imagesInMosaic;      // NumberOfImagesInMosaic
  std::optional<glm::dvec3> sliceNormal;  // SliceNormalVector: the direction tiles go in
};

// Reads the CSA2 ("SV10") layout of BYTES; anything it cannot read (CSA1, damage) is left out.
// Bounded: at most 128 tags and 512 items a tag, every length checked against SIZE.
CsaImageInfo parseCsaImageHeader(const uint8_t* bytes, size_t size);

struct MosaicAttributes {
  bool isMosaic = false;      // ImageType holds MOSAIC
  std::optional<int> images;  // NumberOfImagesInMosaic
  std::string imagesFrom;     // where it was read, for messages
  std::optional<glm::dvec3> sliceNormal;
};

// The mosaic attributes of DS (IMAGE_TYPE: its Image Type): (0019,xx0A) in the SIEMENS MR
// HEADER block first, else the CSA image header.
MosaicAttributes readMosaicAttributes(DcmItem* ds, const std::string& imageType);

// Appends one header per tile of MOSAIC (the whole image's header) to OUT. Returns empty, or
// why the image cannot be split (naming the attribute); OUT is then unchanged.
std::string splitMosaic(const FrameHeader& mosaic, const MosaicAttributes& a,
                        std::vector<FrameHeader>& out);

}  // namespace voxray::dicom
