// Binary DICOM SEG onto the volume of its source series, through DCMTK's dcmseg.
#include <dcmtk/config/osconfig.h>  // first: DCMTK's configuration
#include <dcmtk/dcmdata/dctk.h>
#include <dcmtk/dcmfg/fgpixmsr.h>
#include <dcmtk/dcmfg/fgplanor.h>
#include <dcmtk/dcmfg/fgplanpo.h>
#include <dcmtk/dcmfg/fgseg.h>
#include <dcmtk/dcmiod/cielabutil.h>
#include <dcmtk/dcmseg/segdoc.h>
#include <dcmtk/dcmseg/segment.h>

#include <cmath>
#include <memory>
#include <set>

#include "formats.h"
#include "voxray/io/error.h"

namespace voxray::segfiles {
namespace {

std::string text(DcmItem& item, const DcmTagKey& tag) {
  OFString v;
  item.findAndGetOFStringArray(tag, v);
  return v.c_str();
}

Segment::Code codeOf(CodeSequenceMacro& c) {
  OFString value, scheme, meaning;
  c.getCodeValue(value);
  c.getCodingSchemeDesignator(scheme);
  c.getCodeMeaning(meaning);
  if (std::string(scheme.c_str()) == "99VOXRAY") return {"", "", meaning.c_str()};  // free text
  return {value.c_str(), scheme.c_str(), meaning.c_str()};
}

// The series the SEG says it lies on: those of its Referenced Series Sequence.
std::set<std::string> referencedSeries(DcmItem& d) {
  std::set<std::string> uids;
  DcmSequenceOfItems* seq = nullptr;
  if (d.findAndGetSequence(DCM_ReferencedSeriesSequence, seq).good() && seq)
    for (unsigned long i = 0; i < seq->card(); ++i)
      uids.insert(text(*seq->getItem(i), DCM_SeriesInstanceUID));
  return uids;
}

}  // namespace

Segmentation readSeg(const std::string& path, const Volume& onto) {
  quietDcmtkObjectLibraries();
  DcmFileFormat file;
  OFCondition read = file.loadFile(path.c_str());
  if (read.bad())
    throw inputError(path + ": cannot be read as DICOM (" + read.text() +
                     "); the file is damaged or truncated");
  DcmDataset& d = *file.getDataset();
  if (text(d, DCM_SOPClassUID) != UID_SegmentationStorage)
    throw inputError(path + ": is a DICOM file but not a segmentation (DICOM SEG)");
  if (onto.study.seriesInstanceUid.empty())
    throw inputError(path +
                     ": a DICOM SEG lies on a DICOM series, and this volume was not read "
                     "from DICOM. Open the series it was made on first.");
  const std::set<std::string> series = referencedSeries(d);
  if (!series.empty() && !series.count(onto.study.seriesInstanceUid))
    throw inputError(path + ": this segmentation was made on another series (it references " +
                     *series.begin() + ", the open volume is " + onto.study.seriesInstanceUid +
                     "). Open the series it references, then import it.");
  const std::string frameOfReference = text(d, DCM_FrameOfReferenceUID);
  if (!onto.study.frameOfReferenceUid.empty() && frameOfReference != onto.study.frameOfReferenceUid)
    throw inputError(path + ": this segmentation lies in another frame of reference (" +
                     frameOfReference + ") than the open volume (" +
                     onto.study.frameOfReferenceUid + "): it belongs to another scan");
  Uint16 rows = 0, columns = 0;
  d.findAndGetUint16(DCM_Rows, rows);
  d.findAndGetUint16(DCM_Columns, columns);
  if (int(columns) != onto.dims.x || int(rows) != onto.dims.y)
    throw inputError(path + ": its frames are " + std::to_string(columns) + "x" +
                     std::to_string(rows) + " pixels, the volume's slices " +
                     std::to_string(onto.dims.x) + "x" + std::to_string(onto.dims.y) +
                     ": it was not made on this volume's grid");

  DcmSegmentation* raw = nullptr;
  OFCondition loaded = DcmSegmentation::loadDataset(d, raw);
  std::unique_ptr<DcmSegmentation> doc(raw);
  if (loaded.bad() || !doc)
    throw inputError(path + ": the segmentation cannot be read (" + loaded.text() + ")");
  if (doc->getSegmentationType() != DcmSegTypes::ST_BINARY)
    throw inputError(path + ": is a fractional segmentation; Voxray reads binary DICOM SEG");

  Segmentation seg = emptySegmentation(onto);
  const size_t segments = doc->getNumberOfSegments();
  if (segments > 255)
    throw inputError(path + ": has " + std::to_string(segments) +
                     " segments; Voxray keeps at most 255 in one label map");
  for (size_t n = 1; n <= segments; ++n) {
    DcmSegment* s = doc->getSegment(n);
    if (!s) continue;
    Segment out;
    out.label = uint8_t(n);
    OFString label;
    s->getSegmentLabel(label);
    out.name = label.c_str();
    out.category = codeOf(s->getSegmentedPropertyCategoryCode());
    out.type = codeOf(s->getSegmentedPropertyTypeCode());
    Uint16 L = 0, a = 0, b = 0;
    if (s->getRecommendedDisplayCIELabValue(L, a, b).good()) {
      double r = 0, g = 0, bl = 0;
      IODCIELabUtil::dicomLab2RGB(r, g, bl, L, a, b);
      out.colour = {float(r), float(g), float(bl)};
    }
    seg.segments.push_back(out);
  }

  // The frames' bits one after another, the first pixel in the lowest bit (read here, not
  // through DCMTK 3.6.7, which misplaces frames that start inside a byte).
  const Uint8* bits = nullptr;
  unsigned long bytes = 0;
  if (d.findAndGetUint8Array(DCM_PixelData, bits, &bytes).bad() || !bits)
    throw inputError(path +
                     ": its pixel data cannot be read (compressed or missing); Voxray "
                     "reads uncompressed binary DICOM SEG");
  const size_t needed = (doc->getNumberOfFrames() * size_t(rows) * size_t(columns) + 7) / 8;
  if (bytes < needed)
    throw inputError(path + ": holds " + std::to_string(bytes) + " bytes of pixel data for " +
                     std::to_string(doc->getNumberOfFrames()) + " frames that need " +
                     std::to_string(needed) + ": the file is truncated or damaged");

  // Every frame must lie in the plane of one of the volume's slices.
  FGInterface& groups = doc->getFunctionalGroups();
  const size_t frames = doc->getNumberOfFrames();
  const size_t sliceSize = size_t(onto.dims.x) * size_t(onto.dims.y);
  for (size_t f = 0; f < frames; ++f) {
    const std::string where = path + ": frame " + std::to_string(f + 1);
    auto* orientation = dynamic_cast<FGPlaneOrientationPatient*>(
        groups.get(Uint32(f), DcmFGTypes::EFG_PLANEORIENTPATIENT));
    auto* position =
        dynamic_cast<FGPlanePosPatient*>(groups.get(Uint32(f), DcmFGTypes::EFG_PLANEPOSPATIENT));
    auto* segment =
        dynamic_cast<FGSegmentation*>(groups.get(Uint32(f), DcmFGTypes::EFG_SEGMENTATION));
    if (!orientation || !position || !segment)
      throw inputError(where + " has no position, orientation or segment number");
    Float64 o[6] = {0, 0, 0, 0, 0, 0};
    orientation->getImageOrientationPatient(o[0], o[1], o[2], o[3], o[4], o[5]);
    const glm::dvec3 row(o[0], o[1], o[2]), col(o[3], o[4], o[5]);
    // 1e-4: orientations are written with 6 decimals.
    if (glm::length(row - onto.direction[0]) > 1e-4 || glm::length(col - onto.direction[1]) > 1e-4)
      throw inputError(where +
                       " is oriented otherwise than the volume's slices; Voxray places "
                       "DICOM SEG frames on the slices they were made on");
    auto* measures =
        dynamic_cast<FGPixelMeasures*>(groups.get(Uint32(f), DcmFGTypes::EFG_PIXELMEASURES));
    Float64 dy = onto.spacingMm.y, dx = onto.spacingMm.x;
    if (measures) {
      measures->getPixelSpacing(dy, 0);
      measures->getPixelSpacing(dx, 1);
    }
    if (std::abs(dx - onto.spacingMm.x) > 1e-4 || std::abs(dy - onto.spacingMm.y) > 1e-4)
      throw inputError(where + " has pixels of " + std::to_string(dx) + " x " + std::to_string(dy) +
                       " mm, the volume's are " + std::to_string(onto.spacingMm.x) + " x " +
                       std::to_string(onto.spacingMm.y) + " mm");
    Float64 p[3] = {0, 0, 0};
    position->getImagePositionPatient(p[0], p[1], p[2]);
    const glm::dvec3 ijk = seg.grid.toIndex(glm::dvec3(p[0], p[1], p[2]));
    const double k = std::round(ijk.z);
    // 0.01 voxel: positions are written with 6 decimals; a frame between slices is not ours.
    if (std::abs(ijk.x) > 0.01 || std::abs(ijk.y) > 0.01 || std::abs(ijk.z - k) > 0.01 || k < 0 ||
        k >= onto.dims.z)
      throw inputError(where + " lies at (" + std::to_string(p[0]) + ", " + std::to_string(p[1]) +
                       ", " + std::to_string(p[2]) +
                       ") mm, which is not on a slice of the volume: it was made on another grid");
    Uint16 number = 0;
    segment->getReferencedSegmentNumber(number);
    if (number < 1 || number > segments)
      throw inputError(where + " names segment " + std::to_string(number) +
                       ", which is not in the file");
    uint8_t* slice = seg.labels.data() + size_t(k) * sliceSize;
    const size_t first = f * sliceSize;
    for (size_t i = 0; i < sliceSize; ++i)
      if (bits[(first + i) / 8] & (1u << ((first + i) % 8)))
        slice[i] = uint8_t(number);  // overlaps: the later segment wins
  }
  return seg;
}

}  // namespace voxray::segfiles
