// Input discovery. A DICOMDIR lists its files; when the listed files are missing (copied
// studies often keep the DICOMDIR of another layout) the folder is searched instead.
#include "file_scan.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcmetinf.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "../file_kind.h"
#include "bounded_load.h"
#include "voxray/io/error.h"

namespace fs = std::filesystem;

namespace voxray::dicom {
namespace {

// FOLDER's files, sorted. LINKED_INSIDE: only those that stay in FOLDER once links are
// resolved (a DICOMDIR's folder: a link in it must not reach a file elsewhere).
std::vector<std::string> filesUnder(const fs::path& dir, bool linkedInside = false) {
  std::vector<std::string> out;
  std::error_code ec;
  auto options = fs::directory_options::skip_permission_denied;
  for (fs::recursive_directory_iterator it(dir, options, ec), end; !ec && it != end;
       it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    if (linkedInside && it->is_symlink(ec) &&
        detail::placeInFolder(dir.string(), it->path().string()) != detail::Placement::Inside)
      continue;
    out.push_back(it->path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

struct DicomDirEntries {
  std::vector<std::string> files;  // regular files in the DICOMDIR's folder, links resolved
  int missing = 0;                 // entries that name nothing
  int refused = 0;                 // entries outside the folder, or not regular files
};

// Referenced files of a DICOMDIR; false when PATH is not a DICOMDIR. A ReferencedFileID is
// relative to the DICOMDIR's folder (PS3.10): one that leaves it (an absolute path, an empty
// first component, "..", a link to a file or folder elsewhere) is not read.
bool readDicomDir(const fs::path& path, DicomDirEntries& entries) {
  DcmFileFormat file;
  // Stops at PixelData: an image given as INPUT is not read twice in full.
  if (!loadDicomFile(file, path.string(), DCM_MaxReadLength, DCM_PixelData).empty()) return false;
  OFString sopClass;
  file.getMetaInfo()->findAndGetOFString(DCM_MediaStorageSOPClassUID, sopClass);
  if (sopClass != UID_MediaStorageDirectoryStorage) return false;
  DcmSequenceOfItems* records = nullptr;
  if (file.getDataset()->findAndGetSequence(DCM_DirectoryRecordSequence, records).bad() || !records)
    return true;
  const fs::path folder = fs::absolute(path).parent_path();
  for (unsigned long i = 0; i < records->card(); ++i) {
    OFString id;
    // Records of patients, studies and series reference no file (no or an empty ID).
    if (records->getItem(i)->findAndGetOFStringArray(DCM_ReferencedFileID, id).bad() || id.empty())
      continue;
    std::string rel(id.c_str());
    std::replace(rel.begin(), rel.end(), '\\', '/');
    std::string resolved;
    switch (detail::placeInFolder(folder.string(), (folder / rel).string(), &resolved)) {
      case detail::Placement::Inside:
        entries.files.push_back(resolved);
        break;
      case detail::Placement::Missing:
        ++entries.missing;
        break;
      case detail::Placement::Outside:
      case detail::Placement::NotRegular:
        ++entries.refused;
        break;
    }
  }
  return true;
}

}  // namespace

InputFiles collectInputFiles(const std::string& input) {
  InputFiles result;
  std::error_code ec;
  fs::path path(input);
  if (!fs::exists(path, ec)) throw inputError(input + ": no such file or folder. Check the path.");
  detail::refuseSpecialFile(input);
  if (fs::is_directory(path, ec)) {
    result.files = filesUnder(path);
    if (result.files.empty())
      throw inputError(input +
                       ": the folder holds no files. Choose the folder of a DICOM "
                       "study or one of its files.");
    return result;
  }
  DicomDirEntries entries;
  if (readDicomDir(path, entries)) {
    if (entries.refused > 0)
      result.notes.push_back("the DICOMDIR names " + std::to_string(entries.refused) +
                             " file(s) outside its folder or that are not regular files "
                             "(absolute paths, '..' or links); they were not read");
    if (!entries.files.empty() && entries.missing == 0) {
      std::sort(entries.files.begin(), entries.files.end());
      result.files = std::move(entries.files);
      return result;
    }
    // A DICOMDIR whose entries are gone: the files beside it are the study.
    if (entries.missing > 0 || entries.refused == 0)
      result.notes.push_back("the DICOMDIR lists " + std::to_string(entries.missing) +
                             " file(s) that do not exist; searched its folder instead");
    result.files = filesUnder(fs::absolute(path).parent_path(), true);
    return result;
  }
  result.files = {path.string()};
  result.singleFile = true;
  return result;
}

}  // namespace voxray::dicom
