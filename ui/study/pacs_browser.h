#pragma once
// The study browser's state and work (File > Open from PACS...), Qt-free: the configured
// nodes, a search, the series of an expanded study, and a retrieval into the cache with
// progress and cancel. Network work runs as a BackgroundTask; events arrive through POST
// (the dialog's GUI thread). A retrieval that fails or is cancelled leaves nothing to open.
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "background_task.h"
#include "no_qt.h"

#ifdef VOXRAY_HAS_DICOM
#include "voxray/io/pacs.h"
#include "voxray/io/pacs_cache.h"

namespace voxray {

struct PacsBrowserEvents {
  // A search's studies arrive in pages as the node answers (append them; the first page
  // follows a search at once), then found() with their number and whether the node holds
  // more than kMaxStudies.
  std::function<void(const std::vector<PacsMatch>& page)> studies;
  std::function<void(size_t count, bool more)> found;
  std::function<void(const std::string& studyUid, const std::vector<PacsMatch>& series)> series;
  std::function<void(const RetrieveProgress&)> progress;
  // Open entry.folder with series seriesUid; a whole study (seriesUid empty): the folder
  // holds all its series, for the series picker.
  std::function<void(const CachedSeries&)> retrieved;
  std::function<void(const std::string& message)> failed;
  std::function<void()> cancelled;
  std::function<void()> sent;  // send(): the node took every file
  // echo(): the node answered (its label: the address without secrets).
  std::function<void(const std::string& label)> echoed;
};

class PacsBrowser {
 public:
  // Studies per page: the list fills page by page while the node still answers. Past
  // kMaxStudies a search stops and says so; the user narrows it.
  static constexpr size_t kPageSize = 200;
  static constexpr size_t kMaxStudies = 10000;

  PacsBrowser(PacsBrowserEvents events, std::string cacheFolder = defaultPacsCacheFolder(),
              BackgroundTask::Post post = {});
  ~PacsBrowser();  // cancels and waits

  // The configured nodes (names), then any address typed by the user works too.
  static std::vector<std::string> configuredNodes();

  // Each starts at once on the browser's thread, after the previous job (cancelled first).
  void search(const std::string& node, PacsQuery query);
  void listSeries(const std::string& node, const std::string& studyUid);
  // IMAGES (the series' count from its search, 0: not known) is the progress' total when the
  // transport does not say (WADO-RS).
  void retrieve(const std::string& node, const std::string& studyUid, const std::string& seriesUid,
                int images = 0);
  // Every series of the study into the cache (progress over the whole study), then one
  // folder showing them all (PacsCache::studyFolder).
  void retrieveStudy(const std::string& node, const std::string& studyUid);
  // Sends FILES (C-STORE; STOW-RS): the screenshot export's "Send to". Failure: failed();
  // cancel(): cancelled() (STOW-RS at once; C-STORE once a blocked connect or file returns).
  void send(const std::string& node, std::vector<std::string> files);
  // Checks that NODE answers as voxray-cli pacs echo does (C-ECHO; DICOMweb: a QIDO search
  // with limit 1): echoed() or failed(). The node editor's Test, before the node is saved.
  void echo(PacsNode node);
  void cancel() { task_.cancel(); }
  bool busy() const { return busy_; }

 private:
  void run(std::function<void()> job);
  RetrieveOptions retrieveOptions(int receivedBefore, int total);

  PacsBrowserEvents events_;
  std::string cacheFolder_;
  std::atomic<bool> busy_{false};
  BackgroundTask task_;  // last member: its thread stops before the rest goes
};

}  // namespace voxray
#endif
