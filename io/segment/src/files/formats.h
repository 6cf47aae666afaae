#pragma once
// One writer and reader per file format; segment_files.cpp chooses among them.
#include <string>

#include "label_grid.h"
#include "voxray/io/segment_files.h"

namespace voxray::segfiles {

// Write the file at TEMPORARY (writeWhole renames it); throw on failure.
void writeNifti(const std::string& temporary, const Segmentation& seg);
void writeNrrd(const std::string& temporary, const Segmentation& seg);
WrittenDicomSeg writeSeg(const std::string& temporary, const Segmentation& seg,
                         const StudyIdentity& source, const DicomSegOptions& options);

// DCMTK's dcmiod/dcmfg/dcmseg print warnings on stderr (e.g. about checks they skip while
// reading); what matters comes back as an OFCondition and becomes our message. Errors only.
void quietDcmtkObjectLibraries();

LabelFile readNifti(const std::string& path);
LabelFile readNrrd(const std::string& path);
Segmentation readSeg(const std::string& path, const Volume& onto);

}  // namespace voxray::segfiles
