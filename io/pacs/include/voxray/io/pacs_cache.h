#pragma once
// The local cache of retrieved series: one folder per complete series under the user's cache
// folder, an index of them, least recently used evicted over a size cap that counts all the
// cache writes (series, the studies/ views, the index; as du does). A retrieval is
// staged in a folder of its own and enters the index only when complete, so a cancelled or
// failed one leaves no half series behind. Never under the user's data folders.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "voxray/io/error.h"
#include "voxray/io/pacs.h"

namespace voxray {

class DicomImport;

struct CachedSeries {
  std::string studyUid, seriesUid;
  std::string folder;    // absolute; loadVolume() opens it
  uint64_t bytes = 0;    // on disk (allocated blocks)
  int64_t lastUsed = 0;  // seconds since the epoch
  int images = 0;
};

// $VOXRAY_CACHE_DIR, else $XDG_CACHE_HOME/voxray, else ~/.cache/voxray.
std::string defaultPacsCacheFolder();

class PacsCache {
 public:
  static constexpr uint64_t kDefaultCapBytes = uint64_t(8) << 30;
  explicit PacsCache(std::string root = defaultPacsCacheFolder(),
                     uint64_t capBytes = kDefaultCapBytes);

  // The cached series (and marks it used), or nothing.
  std::optional<CachedSeries> find(const std::string& seriesUid);
  // The series from the cache, else retrieved from CLIENT first. Throws Cancelled on cancel
  // and the client's error on failure (Output saying the cache is full when its file system
  // is); in every case the cache is as before.
  // IMPORT (may be null) gets each file as it arrives, under the path it will have in the
  // cache, so that IMPORT.finish(returned folder) has little left to do.
  CachedSeries retrieve(PacsClient& client, const std::string& studyUid,
                        const std::string& seriesUid, const RetrieveOptions& options = {},
                        DicomImport* import = nullptr);
  std::vector<CachedSeries> entries() const;
  // A folder under studies/ that shows the cached SERIES of one study together (links to
  // their files, made afresh), so the series picker lists them as it lists a study folder.
  // Its links count in the cap: other series are evicted for them, never SERIES.
  std::string studyFolder(const std::string& studyUid, const std::vector<CachedSeries>& series);
  void remove(const std::string& seriesUid);
  const std::string& root() const { return root_; }

 private:
  std::vector<CachedSeries> load() const;
  void save(const std::vector<CachedSeries>& entries) const;
  // Removes least recently used ENTRIES (never those in KEEP) until everything under the
  // root takes at most the cap.
  void evict(std::vector<CachedSeries>& entries, const std::vector<std::string>& keep) const;
  // "WHAT: the cache at ROOT is full: free space or set VOXRAY_CACHE_DIR ... (DETAIL)"
  Error fullError(const std::string& what, const std::string& detail = {}) const;

  std::string root_;
  uint64_t capBytes_;
};

}  // namespace voxray
