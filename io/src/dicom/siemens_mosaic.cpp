#include "siemens_mosaic.h"

#include "private_tags.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcelem.h>
#include <dcmtk/dcmdata/dcitem.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace voxray::dicom {
namespace {

constexpr size_t kCsaTagBytes = 84;               // name[64], vm, vr[4], syngodt, items, 77
constexpr uint32_t kMaxCsaTags = 128;             // dcm2niix's bound too; real headers have ~100
constexpr uint32_t kMaxCsaItems = 512;            // real tags have at most a few dozen
constexpr unsigned long kMaxCsaBytes = 4u << 20;  // real image headers are ~10 KB

uint32_t le32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

std::string text(const uint8_t* p, size_t n) {
  std::string s(reinterpret_cast<const char*>(p), strnlen(reinterpret_cast<const char*>(p), n));
  while (!s.empty() && (s.back() == ' ' || s.back() == '\0')) s.pop_back();
  while (!s.empty() && s.front() == ' ') s.erase(s.begin());
  return s;
}

std::optional<double> number(const std::string& s) {
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

// An unsigned short that may have been read as US or, without a dictionary, as bytes (UN).
std::optional<int> shortValue(DcmItem* ds, const DcmTagKey& tag) {
  DcmElement* e = nullptr;
  if (ds->findAndGetElement(tag, e).bad() || !e) return std::nullopt;
  Uint16 u = 0;
  if (e->getUint16(u).good()) return int(u);
  Uint8* bytes = nullptr;
  if (e->getLength() == 2 && e->getUint8Array(bytes).good() && bytes)
    return int(bytes[0]) | int(bytes[1]) << 8;
  OFString s;
  if (e->getOFString(s, 0).good())
    if (auto v = number(s.c_str())) return int(*v);
  return std::nullopt;
}

}  // namespace

CsaImageInfo parseCsaImageHeader(const uint8_t* p, size_t size) {
  CsaImageInfo out;
  // CSA2 starts "SV10" \4\3\2\1, then the tag count and 77. CSA1 (scanners before ~2004)
  // has no signature and is not read: those mosaics carry (0019,100A) anyway.
  if (!p || size < 16 || std::memcmp(p, "SV10", 4) != 0) return out;
  const uint32_t tags = le32(p + 8);
  if (tags < 1 || tags > kMaxCsaTags) return out;
  size_t at = 16;
  for (uint32_t t = 0; t < tags; ++t) {
    if (size - at < kCsaTagBytes) return out;
    const std::string name = text(p + at, 64);
    const uint32_t items = le32(p + at + 76);
    at += kCsaTagBytes;
    if (items > kMaxCsaItems) return out;
    std::vector<std::string> values;
    for (uint32_t i = 0; i < items; ++i) {
      if (size - at < 16) return out;
      const uint32_t length = le32(p + at + 4);
      at += 16;
      if (length > size - at) return out;
      values.push_back(text(p + at, length));
      at += std::min<size_t>(size - at, (size_t(length) + 3) & ~size_t(3));
    }
    if (name == "NumberOfImagesInMosaic" && !values.empty()) {
      if (auto v = number(values[0]); v && *v == std::floor(*v) && std::abs(*v) < 1e6)
        out.imagesInMosaic = int(*v);
    } else if (name == "SliceNormalVector" && values.size() >= 3) {
      auto x = number(values[0]), y = number(values[1]), z = number(values[2]);
      if (x && y && z) out.sliceNormal = glm::dvec3(*x, *y, *z);
    }
  }
  return out;
}

MosaicAttributes readMosaicAttributes(DcmItem* ds, const std::string& imageType) {
  MosaicAttributes a;
  std::string upper = imageType;
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return char(std::toupper(c)); });
  a.isMosaic = upper.find("MOSAIC") != std::string::npos;
  if (!a.isMosaic || !ds) return a;
  if (auto tag = privateTag(ds, 0x0019, "SIEMENS MR HEADER", 0x0A)) {
    if (auto n = shortValue(ds, *tag)) {
      a.images = n;
      a.imagesFrom = "(0019,100A) NumberOfImagesInMosaic";
    }
  }
  if (auto tag = privateTag(ds, 0x0029, "SIEMENS CSA HEADER", 0x10)) {
    DcmElement* e = nullptr;
    Uint8* bytes = nullptr;
    if (ds->findAndGetElement(*tag, e).good() && e && e->getLength() <= kMaxCsaBytes &&
        e->getUint8Array(bytes).good() && bytes) {
      const CsaImageInfo csa = parseCsaImageHeader(bytes, e->getLength());
      a.sliceNormal = csa.sliceNormal;
      if (!a.images && csa.imagesInMosaic) {
        a.images = csa.imagesInMosaic;
        a.imagesFrom = "NumberOfImagesInMosaic of the CSA image header (0029,1010)";
      }
    }
  }
  return a;
}

std::string splitMosaic(const FrameHeader& m, const MosaicAttributes& a,
                        std::vector<FrameHeader>& out) {
  if (!a.images)
    return "a Siemens mosaic (Image Type MOSAIC) without NumberOfImagesInMosaic "
           "((0019,100A) or the CSA image header (0029,1010)): how many slices it holds is "
           "unknown; convert it with the scanner's or dcm2niix's tools";
  const int n = *a.images;
  const std::string said = a.imagesFrom + " is " + std::to_string(n);
  if (n < 1) return "a Siemens mosaic whose " + said + "; a mosaic holds 1 slice or more";
  const int across = int(std::ceil(std::sqrt(double(n)) - 1e-9));
  const std::string image = std::to_string(m.columns) + "x" + std::to_string(m.rows);
  if (across > m.rows || across > m.columns)
    return "a Siemens mosaic whose " + said + ": more tiles (" + std::to_string(across) + " x " +
           std::to_string(across) + ") than the " + image + " image has pixels";
  if (m.rows % across != 0 || m.columns % across != 0)
    return "a Siemens mosaic whose " + said + ", which Siemens tiles " + std::to_string(across) +
           " x " + std::to_string(across) + ", but the " + image +
           " image does not divide into that square tiling; the attribute or the image is wrong";
  if (!m.hasPosition || !m.hasOrientation || !m.hasPixelSpacing)
    return "a Siemens mosaic without Image Position, Image Orientation or Pixel Spacing: "
           "its slices cannot be placed";
  const double spacing = m.spacingBetweenSlices > 0 ? m.spacingBetweenSlices : m.sliceThickness;
  if (!(spacing > 0))
    return "a Siemens mosaic without Spacing Between Slices (0018,0088) or Slice Thickness "
           "(0018,0050): the distance between its slices is unknown";
  FrameHeader tile = m;
  tile.rows = m.rows / across;
  tile.columns = m.columns / across;
  // The mosaic's Image Position is the corner of the whole tiled image; tile 0 is in the
  // middle of it (dcm2niix moves it by half the size difference along rows and columns).
  const glm::dvec3 first = m.position +
                           m.rowDir * (m.pixelSpacing.x * (m.columns - tile.columns) / 2.0) +
                           m.colDir * (m.pixelSpacing.y * (m.rows - tile.rows) / 2.0);
  // The tiles follow the CSA SliceNormalVector, which may point against row x column
  // (slices stored in descending order); without it, row x column.
  glm::dvec3 normal = m.normal();
  if (a.sliceNormal && glm::length(*a.sliceNormal) > 0.5) {
    const glm::dvec3 csa = glm::normalize(*a.sliceNormal);
    if (std::abs(glm::dot(csa, normal)) > 0.99) normal = csa;
  }
  for (int t = 0; t < n; ++t) {
    tile.position = first + double(t) * spacing * normal;
    tile.mosaic = FrameHeader::MosaicTile{t, n, across, m.rows, m.columns};
    out.push_back(tile);
  }
  return {};
}

}  // namespace voxray::dicom
