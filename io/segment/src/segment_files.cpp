#include "voxray/io/segment_files.h"

#include <array>
#include <cstring>
#include <fstream>

#include "files/formats.h"
#include "files/whole_file.h"
#include "voxray/io/error.h"
#include "voxray/io/segmentation_check.h"

namespace voxray {

void writeSegmentationNifti(const std::string& path, const Segmentation& seg, bool force) {
  checkSegmentation(seg);
  segfiles::writeWhole(path, force,
                       [&](const std::string& temporary) { segfiles::writeNifti(temporary, seg); });
}

void writeSegNrrd(const std::string& path, const Segmentation& seg, bool force) {
  checkSegmentation(seg);
  segfiles::writeWhole(path, force,
                       [&](const std::string& temporary) { segfiles::writeNrrd(temporary, seg); });
}

WrittenDicomSeg writeDicomSeg(const std::string& path, const Segmentation& seg,
                              const StudyIdentity& source, const DicomSegOptions& options) {
  checkSegmentation(seg);
  WrittenDicomSeg uid;
  segfiles::writeWhole(path, options.force, [&](const std::string& temporary) {
    uid = segfiles::writeSeg(temporary, seg, source, options);
  });
  return uid;
}

Segmentation readSegmentationFile(const std::string& path, const Volume& onto) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw inputError(path + ": cannot be opened (does it exist, may it be read?)");
  // What the file is, by its first bytes (names lie): DICOM's preamble and "DICM", NRRD's
  // magic, NIfTI's header size (348 or 540) or gzip's magic for .nii.gz.
  std::array<char, 352> head{};
  in.read(head.data(), head.size());
  const size_t got = size_t(in.gcount());
  Segmentation seg;
  if (got >= 132 && std::memcmp(head.data() + 128, "DICM", 4) == 0) {
    seg = segfiles::readSeg(path, onto);
  } else if (got >= 4 && std::memcmp(head.data(), "NRRD", 4) == 0) {
    seg = segfiles::placeOnVolume(segfiles::readNrrd(path), onto, path);
  } else {
    int32_t size = 0;
    if (got >= 4) std::memcpy(&size, head.data(), 4);
    const bool gzip = got >= 2 && uint8_t(head[0]) == 0x1f && uint8_t(head[1]) == 0x8b;
    const bool nifti = size == 348 || size == 540 || __builtin_bswap32(uint32_t(size)) == 348 ||
                       __builtin_bswap32(uint32_t(size)) == 540;
    if (!gzip && !nifti)
      throw inputError(path +
                       ": is neither NIfTI, NRRD nor DICOM; Voxray reads label maps "
                       "in .nii(.gz), .seg.nrrd/.nrrd and DICOM SEG (.dcm)");
    seg = segfiles::placeOnVolume(segfiles::readNifti(path), onto, path);
  }
  checkSegmentation(seg);
  return seg;
}

}  // namespace voxray
