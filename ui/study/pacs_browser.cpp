#include "pacs_browser.h"

#ifdef VOXRAY_HAS_DICOM
#include "voxray/io/error.h"

namespace voxray {

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
  if (query.limit == 0 || query.limit > kMaxStudies) query.limit = kMaxStudies;
  run([this, node, query] {
    FindOptions options;
    options.pageSize = kPageSize;
    options.cancel = task_.cancelFlag();
    options.page = [this](const std::vector<PacsMatch>& page) {
      task_.post([events = events_, page] {
        if (events.studies) events.studies(page);
      });
    };
    FindResult result = makePacsClient(resolvePacsNode(node))->findPages(query, options);
    task_.post([events = events_, count = result.matches.size(), more = result.more] {
      if (events.found) events.found(count, more);
    });
  });
}

namespace {

std::vector<PacsMatch> findSeries(PacsClient& client, const std::string& studyUid) {
  PacsQuery q;
  q.level = QueryLevel::Series;
  q.studyInstanceUid = studyUid;
  return client.find(q);
}

}  // namespace

void PacsBrowser::listSeries(const std::string& node, const std::string& studyUid) {
  run([this, node, studyUid] {
    auto series = findSeries(*makePacsClient(resolvePacsNode(node)), studyUid);
    task_.post([events = events_, studyUid, series] {
      if (events.series) events.series(studyUid, series);
    });
  });
}

RetrieveOptions PacsBrowser::retrieveOptions(int receivedBefore, int total) {
  RetrieveOptions options;
  options.cancel = task_.cancelFlag();
  options.progress = [this, receivedBefore, total](RetrieveProgress p) {
    p.received += receivedBefore;
    if (total > 0) p.total = total;
    task_.post([events = events_, p] {
      if (events.progress) events.progress(p);
    });
  };
  return options;
}

void PacsBrowser::retrieve(const std::string& node, const std::string& studyUid,
                           const std::string& seriesUid, int images) {
  run([this, node, studyUid, seriesUid, images] {
    auto client = makePacsClient(resolvePacsNode(node));
    PacsCache cache(cacheFolder_);
    CachedSeries entry = cache.retrieve(*client, studyUid, seriesUid, retrieveOptions(0, images));
    task_.post([events = events_, entry] {
      if (events.retrieved) events.retrieved(entry);
    });
  });
}

void PacsBrowser::retrieveStudy(const std::string& node, const std::string& studyUid) {
  run([this, node, studyUid] {
    auto client = makePacsClient(resolvePacsNode(node));
    auto series = findSeries(*client, studyUid);
    if (series.empty())
      throw inputError(
          "The node lists no series in this study: search again, or ask the "
          "PACS administrator");
    int total = 0;
    for (const auto& s : series) total += s.numberOfInstances;
    PacsCache cache(cacheFolder_);
    std::vector<CachedSeries> got;
    CachedSeries study{studyUid, "", "", 0, 0, 0};
    for (const auto& s : series) {
      got.push_back(cache.retrieve(*client, studyUid, s.seriesInstanceUid,
                                   retrieveOptions(study.images, total)));
      study.bytes += got.back().bytes;
      study.images += got.back().images;
    }
    study.folder = cache.studyFolder(studyUid, got);
    task_.post([events = events_, study] {
      if (events.retrieved) events.retrieved(study);
    });
  });
}

void PacsBrowser::send(const std::string& node, std::vector<std::string> files) {
  run([this, node, files = std::move(files)] {
    makePacsClient(resolvePacsNode(node))->store(files, task_.cancelFlag());
    task_.post([events = events_] {
      if (events.sent) events.sent();
    });
  });
}

void PacsBrowser::echo(PacsNode node) {
  run([this, node = std::move(node)] {
    makePacsClient(node)->echo();
    task_.post([events = events_, label = node.label()] {
      if (events.echoed) events.echoed(label);
    });
  });
}

}  // namespace voxray
#endif
