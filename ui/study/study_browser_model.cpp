#include "study_browser_model.h"

#ifdef VOXRAY_HAS_STUDYDB
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <system_error>

#include "thumbnail.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace fs = std::filesystem;

namespace voxray {

std::string missingText(const SeriesEntry& s) {
  if (s.missingFiles == 0) return "";
  if (s.allMissing()) return "files missing (moved or deleted)";
  return std::to_string(s.missingFiles) + " of " + std::to_string(s.row.instanceCount) +
         " files missing";
}

StudyBrowserModel::StudyBrowserModel(std::string folder, StudyBrowserEvents events,
                                     BackgroundTask::Post post)
    : events_(std::move(events)),
      db_(std::make_unique<StudyDb>(std::move(folder))),
      importTask_(post),
      thumbTask_(post) {}

StudyBrowserModel::~StudyBrowserModel() {
  importTask_.cancel();
  thumbTask_.cancel();
  importTask_.wait();
  thumbTask_.wait();
}

bool StudyBrowserModel::hasStudies(const std::string& folder) {
  std::error_code ec;
  if (!fs::exists(fs::path(folder) / "studies.sqlite", ec)) return false;
  try {
    return StudyDb(folder).studyCount() > 0;
  } catch (const std::exception&) {
    return false;  // an unreadable database: the browser says why when the user opens it
  }
}

void StudyBrowserModel::search(const StudyQuery& query) {
  lastQuery_ = query;
  studies_ = db_->find(query);
  group();
}

void StudyBrowserModel::group() {
  patients_.clear();
  // Patients in the order of their newest study (the studies come newest first).
  std::map<std::pair<std::string, std::string>, size_t> index;
  for (size_t i = 0; i < studies_.size(); ++i) {
    const PatientFields& p = studies_[i].patient;
    auto [it, fresh] = index.try_emplace({p.patientId, p.name}, patients_.size());
    if (fresh) patients_.push_back({p, {}});
    patients_[it->second].studies.push_back(i);
  }
}

std::vector<SeriesEntry> StudyBrowserModel::series(const std::string& studyUid) const {
  std::vector<SeriesEntry> out;
  for (SeriesRow& row : db_->series(studyUid)) {
    SeriesEntry e{std::move(row), 0};
    // One stat per file of one study: cheap, and it shows a moved folder before an open fails.
    std::error_code ec;
    for (const auto& i : db_->instances(e.row.series.uid))
      if (!fs::exists(i.instance.path, ec)) ++e.missingFiles;
    out.push_back(std::move(e));
  }
  return out;
}

std::vector<StudyRow> StudyBrowserModel::priors(const std::string& studyUid) const {
  return db_->priors(studyUid);
}

std::pair<std::string, LoadOptions> StudyBrowserModel::openSeries(const std::string& seriesUid) {
  SeriesInput in = db_->seriesInput(seriesUid);
  LoadOptions o;
  o.series = in.series;
  return {in.folder, o};
}

void StudyBrowserModel::researched() {
  studies_ = db_->find(lastQuery_);
  group();
}

int StudyBrowserModel::deleteStudy(const std::string& studyUid) {
  int n = db_->deleteStudy(studyUid);
  researched();
  return n;
}

int StudyBrowserModel::deleteSeries(const std::string& seriesUid) {
  int n = db_->deleteSeries(seriesUid);
  researched();
  return n;
}

void StudyBrowserModel::importPaths(std::vector<std::string> paths, bool copy) {
  importTask_.wait();
  importing_ = true;
  const std::string folder = db_->folder();
  importTask_.start([this, paths = std::move(paths), copy, folder] {
    try {
      StudyDb db(folder);  // its own connection: SQLite may not share one across threads
      ImportOptions o;
      o.copy = copy;
      o.cancel = importTask_.cancelFlag();
      o.progress = [this](int done, int total) {
        importTask_.post([this, done, total] {
          if (events_.importProgress) events_.importProgress(done, total);
        });
      };
      ImportReport report = db.import(paths, o);
      importTask_.post([this, report] {
        importing_ = false;
        researched();
        if (events_.imported) events_.imported(report);
      });
    } catch (const std::exception& e) {
      const std::string message = e.what();
      importTask_.post([this, message] {
        importing_ = false;
        researched();
        if (events_.importFailed) events_.importFailed(message);
      });
    }
  });
}

ImportReport StudyBrowserModel::storeRetrieved(const std::string& cachedFolder) {
  // Copied: the cache evicts, the database keeps what it was given.
  ImportOptions copy;
  copy.copy = true;
  ImportReport r = db_->import({cachedFolder}, copy);
  researched();
  return r;
}

void StudyBrowserModel::makeThumbnails(const std::string& studyUid) {
  thumbTask_.cancel();
  thumbTask_.wait();
  const std::string folder = db_->folder();
  std::vector<SeriesEntry> list = series(studyUid);
  // A folder of links of its own: StudyDb::seriesInput's folder of a series is made afresh
  // each time, so a thumbnail made from it would pull it away from an open of that series.
  const fs::path links = fs::path(folder) / ("thumbnail-links-" + std::to_string(::getpid()) + "-" +
                                             std::to_string(uintptr_t(this)));
  thumbTask_.start([this, folder, list, links] {
    std::unique_ptr<StudyDb> db;
    for (const SeriesEntry& s : list) {
      if (thumbTask_.cancelled()) break;
      Image thumb;
      if (s.missingFiles == 0 && s.row.frameCount <= kMaxThumbnailImages) {
        try {
          if (!db) db = std::make_unique<StudyDb>(folder);
          fs::remove_all(links);
          fs::create_directories(links);
          int n = 0;
          for (const auto& i : db->instances(s.row.series.uid))
            fs::create_symlink(i.instance.path, links / (std::to_string(n++) + ".dcm"));
          LoadOptions o;
          o.series = s.row.series.uid;
          o.cancel = thumbTask_.cancelFlag();
          Volume v = loadVolume(links.string(), o);
          thumb = middleSliceThumbnail(v, defaultThumbnailWindow(v, s.row.series.modality, true));
        } catch (const std::exception&) {
          thumb = {};  // not a volume, a codec io lacks, cancelled: the row has no picture
        }
      }
      if (thumbTask_.cancelled()) break;
      const std::string uid = s.row.series.uid;
      thumbTask_.post([this, uid, thumb] {
        if (events_.thumbnail) events_.thumbnail(uid, thumb);
      });
    }
    std::error_code ec;
    fs::remove_all(links, ec);
  });
}

}  // namespace voxray
#endif
