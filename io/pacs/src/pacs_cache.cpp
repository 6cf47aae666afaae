#include "voxray/io/pacs_cache.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include <nlohmann/json.hpp>

#include "staged_series.h"
#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

int64_t now() {
  return std::chrono::duration_cast<std::chrono::seconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// A folder name for a UID: the UID itself when it is one (digits and dots), else a hash.
std::string folderName(const std::string& uid) {
  bool plain = !uid.empty() && uid.size() <= 64 &&
               uid.find_first_not_of("0123456789.") == std::string::npos && uid[0] != '.';
  return plain ? uid : std::string("h").append(std::to_string(std::hash<std::string>{}(uid)));
}

// Below this much free space where a write failed, the cache's file system counts as full
// (a CT instance is about 0.5 MB; a write that failed with more room left failed otherwise).
constexpr uintmax_t kFullBelowBytes = 4u << 20;

bool fileSystemFull(const std::string& folder) {
  std::error_code ec;
  fs::space_info space = fs::space(folder, ec);
  return !ec && space.available < kFullBelowBytes;
}

// What PATH takes on disk (allocated blocks, as du counts them): its files, folders and links
// themselves (never what links point to). A missing path takes nothing.
uint64_t diskBytes(const fs::path& path) {
  auto blocks = [](const fs::path& p) -> uint64_t {
    struct stat st {};
    return lstat(p.c_str(), &st) == 0 ? uint64_t(st.st_blocks) * 512 : 0;
  };
  uint64_t n = blocks(path);
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(path, ec))) return n;
  for (auto it = fs::recursive_directory_iterator(path, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    n += blocks(it->path());
  return n;
}

}  // namespace

// The index's form (index.json: {"series": [...]}), for nlohmann-json.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(CachedSeries, studyUid, seriesUid, folder, bytes, lastUsed,
                                   images)

std::string defaultPacsCacheFolder() {
  if (const char* dir = std::getenv("VOXRAY_CACHE_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::string(xdg) + "/voxray";
  const char* home = std::getenv("HOME");
  return std::string(home ? home : ".") + "/.cache/voxray";
}

PacsCache::PacsCache(std::string root, uint64_t capBytes)
    : root_(fs::absolute(root).lexically_normal().string()), capBytes_(capBytes) {
  std::error_code ec;
  fs::create_directories(fs::path(root_) / "series", ec);
  fs::create_directories(fs::path(root_) / "staging", ec);
  if (ec)
    throw outputError("Cannot create the PACS cache " + root_ + " (" + ec.message() +
                      "): set VOXRAY_CACHE_DIR to a writable folder");
  // What a crashed or killed retrieval left: it would count against the cap for ever.
  pacs::removeStaleStaging(root_ + "/staging");
  pacs::spreadNewFolders(root_ + "/staging");
}

std::vector<CachedSeries> PacsCache::load() const {
  std::ifstream in(fs::path(root_) / "index.json");
  std::vector<CachedSeries> out;
  if (!in) return out;
  try {
    const nlohmann::json index = nlohmann::json::parse(in);
    for (const auto& s : index.at("series").get<std::vector<CachedSeries>>()) {
      if (fs::is_directory(s.folder)) out.push_back(s);  // a folder removed by hand is gone
    }
  } catch (const nlohmann::json::exception&) {
    return {};  // a broken index forgets the cache; the folders are fetched again
  }
  return out;
}

void PacsCache::save(const std::vector<CachedSeries>& entries) const {
  // Written aside and renamed: a full disk leaves the previous index whole.
  fs::path tmp = fs::path(root_) / ("index.json." + std::to_string(getpid()));
  {
    std::ofstream out(tmp);
    out << nlohmann::json{{"series", entries}}.dump(1);
    if (!out.flush()) {
      out.close();
      std::error_code ignored;
      fs::remove(tmp, ignored);
      throw fullError("Cannot write the PACS cache index");
    }
  }
  fs::rename(tmp, fs::path(root_) / "index.json");
}

std::vector<CachedSeries> PacsCache::entries() const { return load(); }

Error PacsCache::fullError(const std::string& what, const std::string& detail) const {
  return outputError(what + ": the cache at " + root_ +
                     " is full: free space or set VOXRAY_CACHE_DIR to a folder on another disk" +
                     (detail.empty() ? "" : " (" + detail + ")"));
}

std::optional<CachedSeries> PacsCache::find(const std::string& seriesUid) {
  auto all = load();
  for (auto& s : all)
    if (s.seriesUid == seriesUid) {
      s.lastUsed = now();
      save(all);
      return s;
    }
  return std::nullopt;
}

void PacsCache::remove(const std::string& seriesUid) {
  auto all = load();
  auto it = std::find_if(all.begin(), all.end(),
                         [&](const CachedSeries& s) { return s.seriesUid == seriesUid; });
  if (it == all.end()) return;
  std::string folder = it->folder;
  all.erase(it);
  save(all);
  std::error_code ignored;
  fs::remove_all(folder, ignored);
}

void PacsCache::evict(std::vector<CachedSeries>& entries,
                      const std::vector<std::string>& keep) const {
  // The cap counts everything under the root (series, the studies/ views, the index,
  // folders, a retrieval being staged), so the least recently used series go until all fits.
  std::sort(entries.begin(), entries.end(),
            [](const CachedSeries& a, const CachedSeries& b) { return a.lastUsed > b.lastUsed; });
  uint64_t total = diskBytes(root_);
  for (size_t i = entries.size(); i-- > 0 && total > capBytes_;) {
    const CachedSeries& s = entries[i];
    if (std::find(keep.begin(), keep.end(), s.seriesUid) != keep.end()) continue;
    // The study's view links to the series' files: it goes with them.
    fs::path view = fs::path(root_) / "studies" / folderName(s.studyUid);
    uint64_t freed = s.bytes + diskBytes(view);
    std::error_code ignored;
    fs::remove_all(s.folder, ignored);
    fs::remove_all(view, ignored);
    total -= std::min(total, freed);
    entries.erase(entries.begin() + std::ptrdiff_t(i));
  }
}

CachedSeries PacsCache::retrieve(PacsClient& client, const std::string& studyUid,
                                 const std::string& seriesUid, const RetrieveOptions& options,
                                 DicomImport* import) {
  if (auto hit = find(seriesUid)) return *hit;
  std::optional<pacs::StagingFolder> staging;
  try {
    staging.emplace(root_ + "/staging", folderName(seriesUid));
  } catch (const Error&) {
    if (fileSystemFull(root_)) throw fullError("Cannot create a staging folder");
    throw;
  }
  const std::string pattern = staging->path();
  const std::string folder = root_ + "/series/" + folderName(seriesUid);
  // Each file is checked as it arrives (WADO-RS hands over its bytes) and, with IMPORT,
  // decoded; DIMSE files are checked from disk at the end.
  pacs::SeriesCheck check(seriesUid);
  RetrieveOptions withImport = options;
  // The staging folder becomes FOLDER once the series is complete: the import knows each
  // file by the path it will have there.
  auto inFolder = [&](const std::string& path) {
    return folder + "/" + fs::path(path).filename().string();
  };
  // With an import, each file goes to it as soon as it is received (RetrieveOptions::arrived),
  // not after it is written, and is checked from what the import read of it (below): one
  // parse of each file instead of two (~0.05 ms each, on the writer's thread).
  if (import) {
    withImport.arrived = [&](const std::string& path, std::shared_ptr<const std::string> bytes) {
      import->add(inFolder(path), bytes);
      if (options.arrived) options.arrived(path, std::move(bytes));
    };
    withImport.written = options.written;
  } else {
    withImport.written = [&](const std::string& path, std::string content) {
      check.arrived(path, content);
      if (options.written) options.written(path, std::move(content));
    };
  }
  std::vector<std::string> files;
  try {
    files = client.retrieveSeries(studyUid, seriesUid, pattern, withImport);
  } catch (const Error& e) {
    // Judged before the staged files go: they are what filled the disk.
    if (e.kind() != Error::Kind::Cancelled && fileSystemFull(pattern))
      throw fullError("Retrieval stopped, nothing was kept", e.what());
    throw;
  }
  if (options.cancel && options.cancel->load()) throw cancelledError("Retrieval cancelled");
  if (import)
    for (const auto& path : files)
      if (auto id = import->instance(inFolder(path)))
        check.known(path, id->sopClassUid, id->seriesInstanceUid, id->sopInstanceUid);
  if (options.cancel && options.cancel->load()) throw cancelledError("Retrieval cancelled");
  // Complete only once what arrived is the series, whole: a node may send other objects;
  // the files the import did not read are parsed from disk.
  check.verify(pattern, files);
  CachedSeries entry{studyUid, seriesUid, folder, 0, now(), int(files.size())};
  entry.bytes = diskBytes(pattern);
  std::error_code ec;
  fs::remove_all(entry.folder, ec);  // a stale folder the index no longer knows
  fs::rename(pattern, entry.folder, ec);
  if (ec)
    throw outputError("Cannot move the retrieved series into " + entry.folder + " (" +
                      ec.message() + ")");
  staging->kept();
  auto all = load();
  all.push_back(entry);
  evict(all, {seriesUid});
  try {
    save(all);
  } catch (const Error&) {
    fs::remove_all(entry.folder, ec);  // not in the index: not kept
    throw;
  }
  return entry;
}

std::string PacsCache::studyFolder(const std::string& studyUid,
                                   const std::vector<CachedSeries>& series) {
  // Links to files, not folders: the importer's scan does not follow folder links.
  fs::path study = fs::path(root_) / "studies" / folderName(studyUid);
  std::error_code ec;
  fs::remove_all(study, ec);
  for (const auto& s : series) {
    fs::path dir = study / fs::path(s.folder).filename();
    fs::create_directories(dir, ec);
    for (const auto& f : fs::directory_iterator(s.folder, ec)) {
      if (ec) break;
      fs::create_symlink(f.path(), dir / f.path().filename(), ec);
      if (ec) break;
    }
    if (ec && fileSystemFull(root_)) throw fullError("Cannot gather the retrieved study");
    if (ec)
      throw outputError("Cannot gather the retrieved study in " + study.string() + " (" +
                        ec.message() + "): set VOXRAY_CACHE_DIR to a writable folder");
  }
  // The links take room too (a block each where the target path is long): within the cap,
  // other series go first.
  std::vector<std::string> keep;
  for (const auto& s : series) keep.push_back(s.seriesUid);
  auto all = load();
  evict(all, keep);
  save(all);
  return study.string();
}

}  // namespace voxray
