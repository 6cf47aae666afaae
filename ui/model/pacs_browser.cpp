#include "pacs_browser.h"

#ifdef VOXRAY_HAS_DICOM
#include "voxray/io/error.h"

namespace voxray::ui {

PacsBrowser::PacsBrowser(PacsBrowserEvents events, std::string cacheFolder,
                         BackgroundTask::Post post)
    : events_(std::move(events)), cacheFolder_(std::move(cacheFolder)), task_(std::move(post)) {}

PacsBrowser::~PacsBrowser() {
  task_.cancel();
  task_.wait();
}

std::vector<std::string> PacsBrowser::configuredNodes() {
  std::vector<std::string> names;
  try {
    for (const auto& n : loadPacsNodes()) names.push_back(n.name);
  } catch (const Error&) {
    // A broken configuration shows up as the error of the first search that names a node.
  }
  return names;
}

void PacsBrowser::run(std::function<void()> job) {
  task_.cancel();
  busy_ = true;
  task_.start([this, job = std::move(job)] {
    try {
      job();
    } catch (const Error& e) {
      bool cancelled = isCancellation(e) || task_.cancelled();
      std::string message = e.what();
      task_.post([events = events_, cancelled, message] {
        if (cancelled && events.cancelled) events.cancelled();
        if (!cancelled && events.failed) events.failed(message);
      });
    }
    busy_ = false;
  });
}

void PacsBrowser::search(const std::string& node, PacsQuery query) {
  query.level = QueryLevel::Study;
  if (query.limit == 0 || query.limit > kPageSize) query.limit = kPageSize;
  run([this, node, query] {
    auto studies = makePacsClient(resolvePacsNode(node))->find(query);
    task_.post([events = events_, studies] {
      if (events.found) events.found(studies);
    });
  });
}

void PacsBrowser::listSeries(const std::string& node, const std::string& studyUid) {
  run([this, node, studyUid] {
    PacsQuery q;
    q.level = QueryLevel::Series;
    q.studyInstanceUid = studyUid;
    auto series = makePacsClient(resolvePacsNode(node))->find(q);
    task_.post([events = events_, studyUid, series] {
      if (events.series) events.series(studyUid, series);
    });
  });
}

void PacsBrowser::retrieve(const std::string& node, const std::string& studyUid,
                           const std::string& seriesUid) {
  run([this, node, studyUid, seriesUid] {
    auto client = makePacsClient(resolvePacsNode(node));
    PacsCache cache(cacheFolder_);
    RetrieveOptions options;
    options.cancel = task_.cancelFlag();
    options.progress = [this](const RetrieveProgress& p) {
      task_.post([events = events_, p] {
        if (events.progress) events.progress(p);
      });
    };
    CachedSeries entry = cache.retrieve(*client, studyUid, seriesUid, options);
    task_.post([events = events_, entry] {
      if (events.retrieved) events.retrieved(entry);
    });
  });
}

}  // namespace voxray::ui
#endif
