// The KOS is a plain dcmsr document tree: TID 2010 is short (a title, an optional
// description, the images), and DCMTK's template classes have no KOS template.
#include <algorithm>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmsr/dsrdoc.h>

#include "sr_header.h"
#include "voxray/io/dicom_write.h"
#include "voxray/io/error.h"
#include "voxray/io/key_object_selection.h"

namespace voxray {
namespace {

void checkKeyImagesStep(const OFCondition& c, const std::string& what) {
  if (c.bad())
    throw outputError("Cannot build the key object selection (" + what + ": " + c.text() +
                      "); please report this");
}

}  // namespace

std::string writeKeyObjectSelection(const std::string& path, const Volume& v,
                                    const std::vector<int>& slices, const KeyImagesInfo& info) {
  const StudyIdentity& s = v.study;
  if (s.studyInstanceUid.empty() || s.sopClassUid.empty())
    throw inputError(
        "Key images are marked in a DICOM series: this volume was not read from "
        "DICOM");
  if (int(s.sliceSopInstanceUids.size()) != v.dims.z)
    throw inputError(
        "This volume's slices are not its files' images (resampled for a tilt or "
        "uneven gaps, or frames of one file), so no slice can be named as a key "
        "image");
  if (slices.empty()) throw inputError("Give at least one slice to mark as a key image");
  std::vector<int> seen;
  for (int k : slices) {
    if (k < 0 || k >= v.dims.z)
      throw inputError("Slice " + std::to_string(k) + " is not in the series: give 0.." +
                       std::to_string(v.dims.z - 1));
    if (std::find(seen.begin(), seen.end(), k) != seen.end())
      throw inputError("Slice " + std::to_string(k) + " is given twice");
    seen.push_back(k);
  }

  DSRDocument doc(DSRTypes::DT_KeyObjectSelectionDocument);
  DSRDocumentTree& tree = doc.getTree();
  // CID 7010: "Of Interest" is the general reason; a reader's choice says no more.
  if (tree.addContentItem(DSRTypes::RT_isRoot, DSRTypes::VT_Container) == 0)
    checkKeyImagesStep(EC_IllegalCall, "root");
  checkKeyImagesStep(tree.getCurrentContentItem().setConceptName(
                         DSRCodedEntryValue("113000", "DCM", "Of Interest")),
                     "title");
  checkKeyImagesStep(tree.getCurrentContentItem().setTemplateIdentification("2010", "DCMR"),
                     "template");
  bool first = true;
  auto add = [&](DSRTypes::E_ValueType type) {
    if (tree.addContentItem(DSRTypes::RT_contains, type,
                            first ? DSRTypes::AM_belowCurrent : DSRTypes::AM_afterCurrent) == 0)
      checkKeyImagesStep(EC_IllegalCall, "content item");
    first = false;
  };
  if (!info.description.empty()) {
    add(DSRTypes::VT_Text);
    checkKeyImagesStep(tree.getCurrentContentItem().setConceptName(
                           DSRCodedEntryValue("113012", "DCM", "Key Object Description")),
                       "description");
    checkKeyImagesStep(tree.getCurrentContentItem().setStringValue(info.description),
                       "description");
  }
  for (int k : slices) {
    add(DSRTypes::VT_Image);
    checkKeyImagesStep(tree.getCurrentContentItem().setImageReference(DSRImageReferenceValue(
                           s.sopClassUid, s.sliceSopInstanceUids[size_t(k)])),
                       "image");
  }
  report::fileWithImages(doc, s, "9002", "", checkKeyImagesStep);
  report::addEvidence(doc, s, slices, checkKeyImagesStep);
  DcmFileFormat file;
  checkKeyImagesStep(doc.write(*file.getDataset()), "DICOM dataset");
  OFString uid;
  doc.getSOPInstanceUID(uid);
  dicomwrite::saveAtomically(file, path, "key object selection");
  return uid.c_str();
}

}  // namespace voxray
