#pragma once
// A PACS client, Qt-free, with two transports behind one interface: DIMSE (DCMTK dcmnet)
// and DICOMweb (libcurl). Studies are searched, series retrieved into a folder (the cache
// stages them, see pacs_cache.h) and files sent. Every failure throws voxray::Error with a
// message naming the node (never a password) and what to do.
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace voxray {

// Where a PACS lives. DIMSE: dicom://CALLED_AE@host:port; DICOMweb: http(s)://host/prefix.
struct PacsNode {
  enum class Transport { Dimse, Web };
  std::string name;  // the configured name; for an inline node, its address
  Transport transport = Transport::Dimse;
  // DIMSE
  std::string calledAe, host, callingAe = "VOXRAY";
  int port = 104;
  int receivePort = 0;  // C-MOVE: the port of Voxray's own C-STORE receiver; 0 = use C-GET
  // DICOMweb
  std::string baseUrl;  // without a trailing '/', e.g. https://pacs.example/dicom-web
  std::string user, password, bearerToken;
  std::string caFile;  // extra CA bundle; empty = the system store
  // Connect and idle timeout: the most any wait for the node takes, and a transfer gives up
  // once no byte came for this long.
  int timeoutSec = 30;
  // For messages: the address without credentials or query values (tokens).
  std::string label() const;
};

// Parses an inline node ("dicom://AE@host:port", "http(s)://host/prefix"); throws Input.
PacsNode parsePacsNode(const std::string& address);

// The configured nodes, from $XDG_CONFIG_HOME/voxray/pacs-nodes.json (or ~/.config/...); a
// missing file is no nodes. JSON: {"nodes": {"NAME": {"url": "...", "callingAe": "...",
// "receivePort": 11113, "user": "...", "password": "...", "bearerToken": "...",
// "caFile": "...", "timeout": 30}}}.
std::string pacsConfigPath();
std::vector<PacsNode> loadPacsNodes(const std::string& path = pacsConfigPath());
// NAME from the configuration, else an inline address. Throws Input naming both options.
PacsNode resolvePacsNode(const std::string& nameOrAddress,
                         const std::string& configPath = pacsConfigPath());

enum class QueryLevel { Patient, Study, Series };

// Empty fields are not matched. Names may use DICOM wildcards (*, ?); dates are YYYYMMDD.
struct PacsQuery {
  QueryLevel level = QueryLevel::Study;
  std::string patientName, patientId, dateFrom, dateTo, modality, accessionNumber;
  std::string studyInstanceUid;  // required for the series level
  size_t limit = 0;              // most matches to return; 0 = no limit
  size_t offset = 0;             // DICOMweb paging; DIMSE ignores it (no paging in C-FIND)
};

struct PacsMatch {
  std::string patientName, patientId;  // identifying: display on request only
  std::string studyInstanceUid, studyDate, studyDescription, accessionNumber, modalities;
  std::string seriesInstanceUid, seriesDescription;
  int seriesNumber = 0;
  // 0: the node did not say (or sent no whole number); a real study or series has one.
  int numberOfSeries = 0, numberOfInstances = 0;
};

// How a search hands its matches over: in pages, as the node sends them, so a caller shows
// the first ones while a node with 10,000 matches is still answering.
struct FindOptions {
  std::function<void(const std::vector<PacsMatch>& page)> page;  // may be empty
  size_t pageSize = 500;  // matches per page; DICOMweb asks for this many per request
  const std::atomic<bool>* cancel = nullptr;  // true: stop (C-CANCEL), throw Cancelled
  // A search without a limit (or a larger one) stops here, with FindResult::more: a node
  // that sends matches without end (or the same page again) must not fill the memory.
  size_t maxMatches = 100000;
};

struct FindResult {
  std::vector<PacsMatch> matches;  // every page, in order
  // The node holds more than the query's limit (or FindOptions::maxMatches), or it sent a
  // page again (it ignores the offset): the matches are its first ones.
  bool more = false;
};

struct RetrieveProgress {
  int received = 0;  // images so far
  int total = 0;     // 0 when the server does not say
  double megabytes = 0.0;
};

struct RetrieveOptions {
  std::function<void(const RetrieveProgress&)> progress;  // may be empty
  const std::atomic<bool>* cancel = nullptr;              // true: stop, throw Cancelled
  // Each file once it is written, with its content (handed over: the callee may keep it), so
  // that its import can start during the transfer. May be empty; DICOMweb calls it (from the
  // thread that writes the files, one at a time, in order; all before retrieveSeries
  // returns), DIMSE (files written by DCMTK) does not.
  std::function<void(const std::string& path, std::string content)> written;
  // Each file's content as soon as it is received, before it is written (PATH: where it
  // will be), shared with the writer, not copied: its import then never waits for the file
  // system (issue 39 item 8). May be empty; DICOMweb calls it from the receiving thread, in
  // order, all before retrieveSeries returns; DIMSE does not.
  std::function<void(const std::string& path, std::shared_ptr<const std::string> content)> arrived;
};

class PacsClient {
 public:
  virtual ~PacsClient() = default;
  // Throws unless the node answers (C-ECHO; DICOMweb: a QIDO search with limit 1).
  virtual void echo() = 0;
  // Every match (at most query.limit, then more says whether the node holds others),
  // handed to OPTIONS.page in pages as they arrive.
  virtual FindResult findPages(const PacsQuery& query, const FindOptions& options) = 0;
  std::vector<PacsMatch> find(const PacsQuery& query) { return findPages(query, {}).matches; }
  // Writes every instance of the series into FOLDER (which exists); returns the files.
  virtual std::vector<std::string> retrieveSeries(const std::string& studyUid,
                                                  const std::string& seriesUid,
                                                  const std::string& folder,
                                                  const RetrieveOptions& options) = 0;
  // Sends DICOM files (C-STORE; STOW-RS): regular files that parse as DICOM, all checked
  // before anything is sent. Throws naming the first file refused, Cancelled
  // when *cancel becomes true (DIMSE: checked before each file and after the association).
  virtual void store(const std::vector<std::string>& files,
                     const std::atomic<bool>* cancel = nullptr) = 0;
};

std::unique_ptr<PacsClient> makePacsClient(const PacsNode& node);

}  // namespace voxray
