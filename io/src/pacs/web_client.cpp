// The DICOMweb transport: QIDO-RS search, WADO-RS retrieve (multipart/related, streamed to
// files as parts arrive, transfer syntaxes as stored), STOW-RS send.
#include <algorithm>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../dicom/codec_registry.h"
#include "http_session.h"
#include "multipart.h"
#include "transports.h"
#include "voxray/io/error.h"
#include "voxray/io/pacs.h"

namespace voxray::pacs {
namespace {

using nlohmann::json;

const char* kDicomJson = "application/dicom+json";

// The first value of a DICOM JSON attribute as text (PN: its alphabetic form).
std::string value(const json& object, const char* tag) {
  auto it = object.find(tag);
  if (it == object.end() || !it->contains("Value") || (*it)["Value"].empty()) return {};
  const json& v = (*it)["Value"][0];
  if (v.is_object()) return v.value("Alphabetic", "");
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number()) return std::to_string(v.get<long long>());
  return {};
}

std::string values(const json& object, const char* tag) {
  auto it = object.find(tag);
  std::string out;
  if (it == object.end() || !it->contains("Value")) return out;
  for (const auto& v : (*it)["Value"])
    if (v.is_string()) out.append(out.empty() ? "" : "\\").append(v.get<std::string>());
  return out;
}

int number(const json& object, const char* tag) {
  try {
    return std::stoi(value(object, tag));
  } catch (const std::exception&) {
    return 0;
  }
}

PacsMatch toMatch(const json& o) {
  PacsMatch m;
  m.patientName = value(o, "00100010");
  m.patientId = value(o, "00100020");
  m.studyInstanceUid = value(o, "0020000D");
  m.studyDate = value(o, "00080020");
  m.studyDescription = value(o, "00081030");
  m.accessionNumber = value(o, "00080050");
  m.modalities = o.contains("00080061") ? values(o, "00080061") : value(o, "00080060");
  m.numberOfSeries = number(o, "00201206");
  m.numberOfInstances = o.contains("00201208") ? number(o, "00201208") : number(o, "00201209");
  m.seriesInstanceUid = value(o, "0020000E");
  m.seriesDescription = value(o, "0008103E");
  m.seriesNumber = number(o, "00200011");
  return m;
}

std::string fileName(const std::string& folder, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "/%06d.dcm", index);
  return folder + name;
}

class WebClient : public PacsClient {
 public:
  explicit WebClient(PacsNode node) : node_(std::move(node)), http_(node_) {}

  void echo() override { http_.get(node_.baseUrl + "/studies?limit=1", kDicomJson); }

  // QIDO-RS pages by limit and offset: one request per page until a short page (or the
  // query's limit, asked one past to learn whether there are more).
  FindResult findPages(const PacsQuery& q, const FindOptions& options) override {
    FindResult result;
    const size_t pageSize = std::max<size_t>(options.pageSize, 1);
    for (PacsQuery page = q;; page.offset += page.limit) {
      if (options.cancel && options.cancel->load()) throw cancelledError("Search cancelled");
      size_t wanted = q.limit ? q.limit + 1 - result.matches.size() : pageSize;
      page.limit = std::min(pageSize, wanted);
      std::vector<PacsMatch> got = findOnce(page);
      if (q.limit && result.matches.size() + got.size() > q.limit) {
        result.more = true;
        got.resize(q.limit - result.matches.size());
      }
      result.matches.insert(result.matches.end(), got.begin(), got.end());
      if (options.page && !got.empty()) options.page(got);
      if (result.more || got.size() < page.limit) return result;
    }
  }

 private:
  std::vector<PacsMatch> findOnce(const PacsQuery& q) {
    if (q.level == QueryLevel::Patient)
      throw inputError("DICOMweb (QIDO-RS) has no patient-level search: search studies instead");
    std::string url = node_.baseUrl + "/studies";
    if (q.level == QueryLevel::Series) {
      if (q.studyInstanceUid.empty())
        throw inputError("A series search needs the study's Study Instance UID");
      url.append("/").append(http_.escape(q.studyInstanceUid)).append("/series");
    }
    std::string params;
    auto add = [&](const char* key, const std::string& v) {
      if (v.empty()) return;
      params.append(params.empty() ? "?" : "&").append(key).append("=").append(http_.escape(v));
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
    HttpResponse r = http_.get(url + params, kDicomJson);
    std::vector<PacsMatch> matches;
    if (r.status == 204 || r.body.empty()) return matches;
    try {
      for (const auto& o : json::parse(r.body)) matches.push_back(toMatch(o));
    } catch (const json::exception&) {
      throw inputError("DICOMweb " + node_.label() +
                       ": the search answer is not DICOM JSON: it may not be a DICOMweb server");
    }
    return matches;
  }

 public:
  std::vector<std::string> retrieveSeries(const std::string& studyUid, const std::string& seriesUid,
                                          const std::string& folder,
                                          const RetrieveOptions& options) override {
    std::vector<std::string> files;
    RetrieveProgress progress;
    std::unique_ptr<MultipartSplitter> splitter;
    auto onPart = [&](const std::string& headers, std::string content) {
      if (headers.find("content-type") != std::string::npos &&
          headers.find("application/dicom") == std::string::npos)
        throw inputError("a part of the answer is not application/dicom");
      std::string path = fileName(folder, int(files.size()));
      std::ofstream out(path, std::ios::binary);
      out.write(content.data(), std::streamsize(content.size()));
      if (!out.flush())
        throw outputError("cannot write " + path + ": the disk may be full; free space");
      files.push_back(path);
      progress.received = int(files.size());
      progress.megabytes += double(content.size()) / 1e6;
      if (options.written) options.written(path, std::move(content));
      if (options.progress) options.progress(progress);
    };
    auto sink = [&](const char* data, size_t size, const std::string& type) {
      if (!splitter)
        splitter = std::make_unique<MultipartSplitter>(multipartBoundary(type), onPart);
      splitter->feed(data, size);
    };
    std::string url =
        node_.baseUrl + "/studies/" + http_.escape(studyUid) + "/series/" + http_.escape(seriesUid);
    http_.get(url, "multipart/related; type=\"application/dicom\"; transfer-syntax=*", sink,
              options.cancel);
    std::string where = "DICOMweb " + node_.label() + ": series " + seriesUid;
    if (!splitter) throw inputError(where + ": the server sent no images");
    try {
      splitter->finish();
    } catch (const Error& e) {
      throw inputError(where + ": " + e.what());
    }
    if (files.empty()) throw inputError(where + ": the server sent no images");
    return files;
  }

  void store(const std::vector<std::string>& files, const std::atomic<bool>* cancel) override {
    const std::string boundary = "voxray-stow-7d0c1e5a";
    std::string body;
    for (const auto& f : files) {
      std::ifstream in(f, std::ios::binary);
      if (!in) throw inputError("Cannot read " + f + "; nothing was sent");
      std::stringstream content;
      content << in.rdbuf();
      body +=
          "--" + boundary + "\r\nContent-Type: application/dicom\r\n\r\n" + content.str() + "\r\n";
    }
    body += "--" + boundary + "--\r\n";
    HttpResponse r =
        http_.post(node_.baseUrl + "/studies",
                   "multipart/related; type=\"application/dicom\"; boundary=" + boundary, body,
                   kDicomJson, cancel);
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
