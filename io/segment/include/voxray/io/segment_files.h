#pragma once
// Label-map files of a segmentation, written and read back (issue 34): NIfTI (.nii, .nii.gz),
// 3D Slicer's .seg.nrrd (segment names, colours, codes in its header) and binary DICOM SEG
// (.dcm) that references its source series, so that PACS and viewers place it on the CT.
//
// Every writer writes a temporary file beside PATH and renames it: PATH appears whole or not
// at all. An existing PATH is kept unless FORCE. Each throws voxray::Error (Output for a file
// that cannot be written or exists, Input for a segmentation that cannot be written so).
#include <string>

#include "voxray/io/segmentation.h"
#include "voxray/io/volume.h"

namespace voxray {

// NIfTI-1 label map, uint8 (0 = no segment), qform and sform both the grid in RAS as NIfTI
// wants (LPS x and y negated). Names and colours are not kept: NIfTI has no place for them.
void writeSegmentationNifti(const std::string& path, const Segmentation& seg, bool force = false);

// 3D Slicer's segmentation file: a gzip NRRD in left-posterior-superior space, one layer,
// with SegmentN_Name, _Color, _LabelValue, _Layer, _Extent, _ID and _Tags (the category and
// type codes as Slicer's TerminologyEntry) for each segment.
void writeSegNrrd(const std::string& path, const Segmentation& seg, bool force = false);

struct DicomSegOptions {
  enum class Algorithm { Manual, SemiAutomatic, Automatic };
  Algorithm algorithm = Algorithm::SemiAutomatic;
  std::string algorithmName = "Voxray";  // required by the IOD unless Manual
  std::string seriesDescription = "Segmentation";
  int seriesNumber = 300;
  bool force = false;  // replace an existing file
};

// Binary DICOM SEG of every segment: one frame per slice where the segment has voxels, on
// the source's Frame of Reference, with the Referenced Series Sequence naming SOURCE's series
// and, where SOURCE has them (sliceSopInstanceUids), each frame's source image. The patient
// and study are SOURCE's (the IOD requires the same patient); nothing identifying is logged.
// An empty segment is refused (a SEG segment needs a frame). Returns the SEG's SOP Instance
// and Series Instance UIDs (an SR that references it lists it as evidence by both). Throws an
// Input error when SOURCE has no study/series/frame of reference UID (the volume was not read
// from DICOM) or the grid does not match SOURCE's slices.
struct WrittenDicomSeg {
  std::string sopInstanceUid, seriesInstanceUid;
};
WrittenDicomSeg writeDicomSeg(const std::string& path, const Segmentation& seg,
                              const StudyIdentity& source, const DicomSegOptions& options = {});

// Reads any of the three (by content: NIfTI, NRRD, DICOM) onto ONTO's grid. A NIfTI or NRRD
// label map must lie on that grid (Input error naming the difference otherwise; nothing is
// resampled). A DICOM SEG's frames are placed by their positions onto ONTO's slices; one that
// references another series or frame of reference is refused; where its segments overlap,
// the later segment's label is kept (one label per voxel). Segments are numbered as in the
// SEG (label = segment number).
Segmentation readSegmentationFile(const std::string& path, const Volume& onto);

}  // namespace voxray
