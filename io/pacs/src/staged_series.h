#pragma once
// The PACS cache's staging folders (staging/<series>-XXXXXX): a retrieval writes there and
// the folder becomes the cached series only once what arrived is checked to be the whole
// series. Each live staging folder is held by a lock (flock), so that a cache opened later
// removes only the ones a crashed or killed retrieval left behind.
#include <map>
#include <string>
#include <vector>

namespace voxray::pacs {

class StagingFolder {
 public:
  // Creates STAGING_ROOT/NAME-XXXXXX and locks it; throws Output when it cannot.
  StagingFolder(const std::string& stagingRoot, const std::string& name);
  // Removes the folder unless it was kept (renamed into the cache).
  ~StagingFolder();
  StagingFolder(const StagingFolder&) = delete;
  StagingFolder& operator=(const StagingFolder&) = delete;
  const std::string& path() const { return path_; }
  void kept() { path_.clear(); }

 private:
  std::string path_;
  int fd_ = -1;  // holds the lock
};

// Asks the file system to place each new folder in STAGING_ROOT away from its siblings
// (ext4's "top of a hierarchy" hint, FS_TOPDIR_FL; other file systems ignore it). A series'
// files take their inodes near their folder's, and ext4 without a journal skips, one by one
// for every new file, the inodes freed there in the last minutes: after a series of 400
// files was removed (evicted, or the cache cleared), the next 400 took ~0.07 s of CPU to
// create instead of ~0.01 s (issue 39 item 8, measured with perf on the Xeon's ext4).
void spreadNewFolders(const std::string& stagingRoot);

// Removes the staging folders no live retrieval holds (left by a crash or a kill). Folders
// younger than a minute stay: their retrieval may not have locked them yet.
void removeStaleStaging(const std::string& stagingRoot);

// Throws Input (nothing kept) unless FILES are all FOLDER holds and each parses as DICOM
// with Series Instance UID SERIES_UID, a SOP Class UID and its own SOP Instance UID.
void verifyStagedSeries(const std::string& folder, const std::string& seriesUid,
                        const std::vector<std::string>& files);

// verifyStagedSeries made as the files arrive: each one handed to arrived() is checked from
// its bytes in memory then, so that once a WADO-RS transfer ends nothing is read back from
// disk (400 CT files re-opened and parsed were on the critical path: issue 39 item 8).
class SeriesCheck {
 public:
  explicit SeriesCheck(std::string seriesUid) : seriesUid_(std::move(seriesUid)) {}
  // BYTES: the whole content just written at PATH.
  void arrived(const std::string& path, const std::string& bytes);
  // PATH's identity, as an import that parsed it read it (an image it decoded): the same
  // verdict as arrived() without parsing the file again.
  void known(const std::string& path, const std::string& sopClassUid, const std::string& seriesUid,
             const std::string& sopInstanceUid);
  // verifyStagedSeries(FOLDER, the series, FILES), reading from disk only the FILES that
  // did not pass through arrived() (DIMSE: DCMTK writes them).
  void verify(const std::string& folder, const std::vector<std::string>& files) const;

 private:
  struct Checked {
    std::string why;  // empty: an image of the series
    std::string instance;
  };
  Checked check(const std::string& path) const;
  std::string seriesUid_;
  std::map<std::string, Checked> arrived_;  // by path
};

}  // namespace voxray::pacs
