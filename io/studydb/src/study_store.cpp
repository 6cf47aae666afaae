#include "study_store.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>

#include "voxray/io/error.h"

namespace fs = std::filesystem;

namespace voxray::studydb {

std::string uidFileName(const std::string& uid) {
  bool plain = !uid.empty() && uid.size() <= 64 &&
               uid.find_first_not_of("0123456789.") == std::string::npos && uid[0] != '.';
  return plain ? uid : std::string("h").append(std::to_string(std::hash<std::string>{}(uid)));
}

namespace {

bool sameContent(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::file_size(a, ec) != fs::file_size(b, ec) || ec) return false;
  std::ifstream x(a, std::ios::binary), y(b, std::ios::binary);
  return std::equal(std::istreambuf_iterator<char>(x), std::istreambuf_iterator<char>(),
                    std::istreambuf_iterator<char>(y));
}

}  // namespace

std::string StudyStore::copyIn(const std::string& source, const std::string& studyUid,
                               const std::string& seriesUid, const std::string& sopUid) const {
  fs::path dir = fs::path(root_) / uidFileName(studyUid) / uidFileName(seriesUid);
  fs::path target = dir / (uidFileName(sopUid) + ".dcm");
  // Another file with this SOP Instance UID and other content is kept beside it (the issue's
  // duplicates: keep both, warn); the same content again replaces its own copy.
  for (int n = 2; fs::exists(target) && !sameContent(source, target); ++n)
    target = dir / (uidFileName(sopUid) + "-" + std::to_string(n) + ".dcm");
  std::error_code ec;
  fs::create_directories(dir, ec);
  // Written aside and renamed: a full disk leaves no half file under the instance's name.
  fs::path part = dir / (target.filename().string() + ".part" + std::to_string(getpid()));
  if (!ec) fs::copy_file(source, part, fs::copy_options::overwrite_existing, ec);
  if (!ec) fs::rename(part, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(part, ignored);
    throw outputError("Cannot copy " + source + " into the study database's store " + root_ + " (" +
                      ec.message() + "): free space there or choose another database with --db");
  }
  return target.string();
}

std::string StudyStore::seriesView(const std::string& views, const std::string& seriesUid,
                                   const std::vector<std::string>& files) const {
  // Made afresh each time: the files may have been imported again from elsewhere since.
  fs::path dir = fs::path(views) / uidFileName(seriesUid);
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir, ec);
  for (size_t i = 0; i < files.size() && !ec; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "%06zu.dcm", i);
    fs::create_symlink(files[i], dir / name, ec);
  }
  if (ec)
    throw outputError("Cannot make the series view " + dir.string() + " (" + ec.message() +
                      "): check that the study database's folder is writable");
  return dir.string();
}

}  // namespace voxray::studydb
