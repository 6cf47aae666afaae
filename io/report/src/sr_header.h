#pragma once
// What the SR and KOS writers share of their DSRDocument: the header that files the document
// with the images it is about, and those images as its evidence.
#include <functional>
#include <string>
#include <vector>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmsr/dsrdoc.h>

#include "voxray/io/volume.h"

namespace voxray::report {

// Each writer's own "cannot build the ..." error for a failed DCMTK call named WHAT.
using Check = std::function<void(const OFCondition& condition, const std::string& what)>;

// UTF-8 text (StudyIdentity holds UTF-8), a new series of Voxray's (SERIES_NUMBER, and
// SERIES_DESCRIPTION when not empty) in the images' study, with their patient and study
// attributes: a PACS files the document with them (secondary_capture.cpp says why the patient
// is copied). These values go into the header only, never into names or logs.
void fileWithImages(DSRDocument& doc, const StudyIdentity& s, const std::string& seriesNumber,
                    const std::string& seriesDescription, const Check& check);

// The images of SLICES (indices into s.sliceSopInstanceUids) as the document's Current
// Requested Procedure Evidence (Type 1 in a KOS, PS3.3 C.17.6.2; 1C in an SR, C.17.2.2).
void addEvidence(DSRDocument& doc, const StudyIdentity& s, const std::vector<int>& slices,
                 const Check& check);

}  // namespace voxray::report
