// The DICOMweb transport: QIDO-RS search, WADO-RS retrieve (multipart/related, streamed to
// files as parts arrive, transfer syntaxes as stored), STOW-RS send.
#include <algorithm>

#include <nlohmann/json.hpp>

#include "dicom/codec_registry.h"
#include "dicom_json.h"
#include "http_session.h"
#include "multipart.h"
#include "pacs_messages.h"
#include "part_writer.h"
#include "sendable.h"
#include "transports.h"
#include "voxray/io/error.h"
#include "voxray/io/pacs.h"

namespace voxray::pacs {
namespace {

using nlohmann::json;

const char* kDicomJson = "application/dicom+json";

std::string fileName(const std::string& folder, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "/%06d.dcm", index);
  return folder + name;
}

class WebClient : public PacsClient {
 public:
  explicit WebClient(PacsNode node) : node_(std::move(node)), http_(node_) {}

  // A QIDO search that answers 200 with DICOM JSON (or 204, nothing): a redirect (to a login
  // page) or a web page is not a DICOMweb server's answer.
  void echo() override { dicomJson(http_.get(url("/studies", "limit=1"), kDicomJson)); }

  // QIDO-RS pages by limit and offset: one request per page until a short page (or the
  // query's limit, asked one past to learn whether there are more). A page that repeats the
  // one before (a node that ignores offset) or the cap on matches ends it, with "more".
  FindResult findPages(const PacsQuery& q, const FindOptions& options) override {
    FindResult result;
    const size_t pageSize = std::max<size_t>(options.pageSize, 1);
    const size_t limit = q.limit ? std::min(q.limit, options.maxMatches) : options.maxMatches;
    std::vector<PacsMatch> last;
    for (PacsQuery page = q;; page.offset += page.limit) {
      if (options.cancel && options.cancel->load()) throw cancelledError("Search cancelled");
      page.limit = std::min(pageSize, limit + 1 - result.matches.size());
      std::vector<PacsMatch> got = findOnce(page);
      if (got.size() > page.limit) got.resize(page.limit);  // a node that ignores limit
      if (!got.empty() && samePage(got, last)) {
        result.more = true;
        return result;
      }
      last = got;
      if (result.matches.size() + got.size() > limit) {
        result.more = true;
        got.resize(limit - result.matches.size());
      }
      result.matches.insert(result.matches.end(), got.begin(), got.end());
      if (options.page && !got.empty()) options.page(got);
      if (result.more || got.size() < page.limit) return result;
    }
  }

 private:
  static bool samePage(const std::vector<PacsMatch>& a, const std::vector<PacsMatch>& b) {
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](const PacsMatch& x, const PacsMatch& y) {
             return x.studyInstanceUid == y.studyInstanceUid &&
                    x.seriesInstanceUid == y.seriesInstanceUid;
           });
  }

  // The node's base URL with PATH added, and its own query (a token) after PARAMS.
  std::string url(const std::string& path, const std::string& params = {}) const {
    const size_t q = node_.baseUrl.find('?');
    std::string query = q == std::string::npos ? "" : node_.baseUrl.substr(q + 1);
    if (!params.empty()) query = params + (query.empty() ? "" : "&" + query);
    return node_.baseUrl.substr(0, q) + path + (query.empty() ? "" : "?" + query);
  }

  // The DICOM JSON array of a QIDO answer (none for 204 or an empty body); throws Input for
  // anything else.
  json dicomJson(const HttpResponse& r) const {
    std::string why;
    if (r.status == 204 || (r.status == 200 && r.body.empty())) return json::array();
    if (r.status != 200) {
      why = "it answered HTTP " + std::to_string(r.status) +
            (r.status >= 300 && r.status < 400 ? " (a redirect)" : "");
    } else {
      json answer = json::parse(r.body, nullptr, false);
      if (answer.is_array()) return answer;
      why = "its answer is not DICOM JSON";
    }
    throw inputError("DICOMweb " + node_.label() + ": " + why +
                     ": it may not be a DICOMweb server; check the node's base URL (e.g. "
                     ".../dicom-web)");
  }

  // A 404 for one study's resource: whether the node lacks the study (a search for it finds
  // nothing) or just the series. False when the node does not answer searches either: then
  // the base URL is wrong, as the 404 said.
  bool studyKnown(const std::string& studyUid, bool& nodeAnswers) {
    nodeAnswers = false;
    try {
      json found = dicomJson(http_.get(
          url("/studies", "StudyInstanceUID=" + http_.escape(studyUid) + "&limit=1"), kDicomJson));
      nodeAnswers = true;
      return !found.empty();
    } catch (const Error&) {
      return false;
    }
  }

  std::vector<PacsMatch> findOnce(const PacsQuery& q) {
    if (q.level == QueryLevel::Patient)
      throw inputError("DICOMweb (QIDO-RS) has no patient-level search: search studies instead");
    std::string path = "/studies";
    if (q.level == QueryLevel::Series) {
      if (q.studyInstanceUid.empty())
        throw inputError("A series search needs the study's Study Instance UID");
      path.append("/").append(http_.escape(q.studyInstanceUid)).append("/series");
    }
    std::string params;
    auto add = [&](const char* key, const std::string& v) {
      if (v.empty()) return;
      params.append(params.empty() ? "" : "&").append(key).append("=").append(http_.escape(v));
    };
    add("PatientName", q.patientName);
    add("PatientID", q.patientId);
    if (!q.dateFrom.empty() || !q.dateTo.empty()) add("StudyDate", q.dateFrom + "-" + q.dateTo);
    add(q.level == QueryLevel::Series ? "Modality" : "ModalitiesInStudy", q.modality);
    add("AccessionNumber", q.accessionNumber);
    if (q.limit) add("limit", std::to_string(q.limit));
    if (q.offset) add("offset", std::to_string(q.offset));
    for (const char* field :
         {"00081030", "00201206", "00201208", "0008103E", "00201209", "00080061", "00200011"})
      add("includefield", field);
    std::vector<PacsMatch> matches;
    json answer;
    try {
      answer = dicomJson(http_.get(url(path, params), kDicomJson));
    } catch (const Error&) {
      // A study the node does not hold has no series: no matches, as C-FIND says.
      bool nodeAnswers = false;
      if (q.level == QueryLevel::Series && http_.lastStatus() == 404 &&
          !studyKnown(q.studyInstanceUid, nodeAnswers) && nodeAnswers)
        return matches;
      throw;
    }
    for (const auto& o : answer)
      if (o.is_object()) matches.push_back(toMatch(o));
    return matches;
  }

 public:
  std::vector<std::string> retrieveSeries(const std::string& studyUid, const std::string& seriesUid,
                                          const std::string& folder,
                                          const RetrieveOptions& options) override {
    std::vector<std::string> files;
    RetrieveProgress progress;
    std::unique_ptr<MultipartSplitter> splitter;
    // This thread receives; the files are written (and handed to options.written) on the
    // writer's (part_writer.h).
    PartWriter writer(options.written);
    auto onPart = [&](const std::string& headers, std::string content) {
      if (headers.find("content-type") != std::string::npos &&
          headers.find("application/dicom") == std::string::npos)
        throw inputError("a part of the answer is not application/dicom");
      std::string path = fileName(folder, int(files.size()));
      files.push_back(path);
      progress.received = int(files.size());
      progress.megabytes += double(content.size()) / 1e6;
      auto shared = std::make_shared<std::string>(std::move(content));
      if (options.arrived) options.arrived(path, shared);
      writer.add(std::move(path), std::move(shared));
      if (options.progress) options.progress(progress);
    };
    auto sink = [&](const char* data, size_t size, const std::string& type) {
      if (!splitter)
        splitter = std::make_unique<MultipartSplitter>(multipartBoundary(type), onPart);
      splitter->feed(data, size);
    };
    try {
      http_.get(url("/studies/" + http_.escape(studyUid) + "/series/" + http_.escape(seriesUid)),
                "multipart/related; type=\"application/dicom\"; transfer-syntax=*", sink,
                options.cancel);
    } catch (const Error& e) {
      bool nodeAnswers = false;
      if (e.kind() == Error::Kind::Cancelled || http_.lastStatus() != 404) throw;
      const bool known = studyKnown(studyUid, nodeAnswers);
      if (!nodeAnswers) throw;  // the base URL is wrong, as the 404 said
      throw inputError(unknownSeriesMessage(node_, studyUid, seriesUid, known));
    }
    std::string where = "DICOMweb " + node_.label() + ": series " + seriesUid;
    if (!splitter) throw inputError(where + ": the server sent no images");
    try {
      splitter->finish();
    } catch (const Error& e) {
      throw inputError(where + ": " + e.what());
    }
    if (files.empty()) throw inputError(where + ": the server sent no images");
    writer.finish();
    return files;
  }

  void store(const std::vector<std::string>& files, const std::atomic<bool>* cancel) override {
    const std::string boundary = "voxray-stow-7d0c1e5a";
    std::string body;
    for (const auto& f : loadSendableFiles(files))
      body += "--" + boundary + "\r\nContent-Type: application/dicom\r\n\r\n" + *f.bytes + "\r\n";
    body += "--" + boundary + "--\r\n";
    HttpResponse r = http_.post(
        url("/studies"), "multipart/related; type=\"application/dicom\"; boundary=" + boundary,
        body, kDicomJson, cancel);
    try {
      json answer = r.body.empty() ? json::object() : json::parse(r.body);
      if (answer.contains("00081198") && answer["00081198"].contains("Value") &&
          !answer["00081198"]["Value"].empty())
        throw inputError("DICOMweb " + node_.label() + " refused " +
                         std::to_string(answer["00081198"]["Value"].size()) + " of " +
                         std::to_string(files.size()) + " files (STOW-RS FailedSOPSequence)");
    } catch (const json::exception&) {
      throw inputError("DICOMweb " + node_.label() + ": the STOW-RS answer is not DICOM JSON");
    }
  }

 private:
  PacsNode node_;
  HttpSession http_;
};

}  // namespace

std::unique_ptr<PacsClient> makeWebClient(const PacsNode& node) {
  return std::make_unique<WebClient>(node);
}

}  // namespace voxray::pacs

namespace voxray {

std::unique_ptr<PacsClient> makePacsClient(const PacsNode& node) {
  // DCMTK's log off (as for import): Voxray reports through Error, and DIMSE log lines
  // would carry patient names.
  dicom::ensureCodecsRegistered();
  if (node.transport == PacsNode::Transport::Web) return pacs::makeWebClient(node);
  return pacs::makeDimseClient(node);
}

}  // namespace voxray
