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

std::vector<std::string> filesUnder(const fs::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  auto options = fs::directory_options::skip_permission_denied;
  for (fs::recursive_directory_iterator it(dir, options, ec), end; !ec && it != end;
       it.increment(ec)) {
    if (it->is_regular_file(ec)) out.push_back(it->path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Referenced files of a DICOMDIR; empty when PATH is not a DICOMDIR.
bool readDicomDir(const fs::path& path, std::vector<std::string>& files, int& missing) {
  DcmFileFormat file;
  // Stops at PixelData: an image given as INPUT is not read twice in full.
  if (!loadDicomFile(file, path.string(), DCM_MaxReadLength, DCM_PixelData).empty()) return false;
  OFString sopClass;
  file.getMetaInfo()->findAndGetOFString(DCM_MediaStorageSOPClassUID, sopClass);
  if (sopClass != UID_MediaStorageDirectoryStorage) return false;
  DcmSequenceOfItems* records = nullptr;
  if (file.getDataset()->findAndGetSequence(DCM_DirectoryRecordSequence, records).bad() || !records)
    return true;
  for (unsigned long i = 0; i < records->card(); ++i) {
    OFString id;
    if (records->getItem(i)->findAndGetOFStringArray(DCM_ReferencedFileID, id).bad()) continue;
    std::string rel(id.c_str());
    std::replace(rel.begin(), rel.end(), '\\', '/');
    fs::path full = path.parent_path() / rel;
    std::error_code ec;
    if (fs::is_regular_file(full, ec))
      files.push_back(full.string());
    else
      ++missing;
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
  std::vector<std::string> listed;
  int missing = 0;
  if (readDicomDir(path, listed, missing)) {
    if (!listed.empty() && missing == 0) {
      std::sort(listed.begin(), listed.end());
      result.files = std::move(listed);
      return result;
    }
    // A DICOMDIR whose entries are gone: the files beside it are the study.
    result.notes.push_back("the DICOMDIR lists " + std::to_string(missing) +
                           " file(s) that do not exist; searched its folder instead");
    result.files = filesUnder(path.parent_path());
    return result;
  }
  result.files = {path.string()};
  result.singleFile = true;
  return result;
}

}  // namespace voxray::dicom
