#pragma once
// HTTP for DICOMweb, and for OME-Zarr over http(s), through libcurl: authentication (basic,
// bearer), TLS with the system CA store (or the node's caFile), timeouts, cancel, and HTTP
// failures worded for the user. Passwords and tokens go to libcurl only, never into a message.
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "voxray/io/pacs.h"

namespace voxray::pacs {

// What a body kept in memory may take: a search's or a store's DICOM JSON answer (a page of
// 500 studies is about 1 MiB), and the start of an HTTP error's body. Retrievals stream to
// a sink instead.
constexpr size_t kMaxAnswerBytes = size_t(64) << 20;
constexpr size_t kMaxErrorBodyBytes = size_t(64) << 10;
// The least a transfer must move within the node's timeout to count as answering.
constexpr long kLeastProgressBytes = 1024;

struct HttpResponse {
  long status = 0;
  std::string contentType;
  std::string body;  // empty when the body went to a sink
};

// Whom the requests serve, for messages: a configured DICOMweb node, or an OME-Zarr URL (the
// node is made from the URL; there is no configuration to point to).
enum class HttpService { DicomWeb, OmeZarr };

class HttpSession {
 public:
  explicit HttpSession(PacsNode node, HttpService service = HttpService::DicomWeb);
  ~HttpSession();
  HttpSession(const HttpSession&) = delete;
  HttpSession& operator=(const HttpSession&) = delete;

  // GET; with SINK, the body is handed over as it arrives (after the headers). Throws Input
  // for connection, TLS and HTTP >= 400 failures, Cancelled when *cancel becomes true.
  using Sink = std::function<void(const char*, size_t, const std::string& contentType)>;
  HttpResponse get(const std::string& url, const std::string& accept, const Sink& sink = {},
                   const std::atomic<bool>* cancel = nullptr);
  HttpResponse post(const std::string& url, const std::string& contentType, const std::string& body,
                    const std::string& accept, const std::atomic<bool>* cancel = nullptr);
  // Percent-encodes a query value (keeping the wildcard *).
  std::string escape(const std::string& value);
  // The HTTP status of the last request (0: none came), also when it threw.
  long lastStatus() const { return lastStatus_; }

 private:
  HttpResponse perform(const std::string& what, const std::string& url,
                       const std::vector<std::string>& headers, const Sink& sink,
                       const std::atomic<bool>* cancel);

  PacsNode node_;
  HttpService service_;
  void* curl_;
  long lastStatus_ = 0;
};

}  // namespace voxray::pacs
