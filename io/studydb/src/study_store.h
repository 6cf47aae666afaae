#pragma once
// The database's own files: copies of instances it owns (PACS retrievals, `db import
// --copy`) under store/STUDY/SERIES/SOP.dcm, and the folders of links through which
// loadVolume opens one series (views/SERIES). Names come from UIDs, never patient data.
#include <string>
#include <vector>

namespace voxray::studydb {

// A file or folder name for a UID: the UID itself when it is one (digits and dots), else a
// hash of it.
std::string uidFileName(const std::string& uid);

class StudyStore {
 public:
  explicit StudyStore(std::string root) : root_(std::move(root)) {}
  // Copies SOURCE into the store (replacing an earlier copy of the same instance) and
  // returns its path. Throws Error (Output) naming the disk when it is full.
  std::string copyIn(const std::string& source, const std::string& studyUid,
                     const std::string& seriesUid, const std::string& sopUid) const;
  // A fresh folder VIEWS/SERIES of links to FILES, numbered in their order.
  std::string seriesView(const std::string& views, const std::string& seriesUid,
                         const std::vector<std::string>& files) const;

 private:
  std::string root_;
};

}  // namespace voxray::studydb
