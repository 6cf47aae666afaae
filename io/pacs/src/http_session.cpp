#include "http_session.h"

#include <sys/stat.h>

#include <algorithm>
#include <chrono>

#include <curl/curl.h>

#include "pacs_messages.h"
#include "voxray/io/error.h"

namespace voxray::pacs {
namespace {

struct Transfer {
  const HttpSession::Sink* sink = nullptr;
  const std::atomic<bool>* cancel = nullptr;
  HttpResponse* response = nullptr;
  CURL* curl = nullptr;
  std::string sinkError;
  // The idle timeout, kept here: libcurl's low-speed check averages over its window, so
  // after a fast start a frozen server held a transfer about twice the timeout.
  // A transfer moves on when kLeastProgressBytes have moved since it last did: a server that
  // drips a byte at a time (a slow loris) stalls as one that sends nothing.
  int timeoutSec = 0;
  curl_off_t moved = 0;
  std::chrono::steady_clock::time_point lastMove = std::chrono::steady_clock::now();
  bool stalled = false;
  bool dripping = false;      // stalled with some bytes moved in the window
  bool errorBodyCut = false;  // an HTTP error's body stopped at kMaxErrorBodyBytes
};

size_t onBody(char* data, size_t size, size_t n, void* user) {
  auto* t = static_cast<Transfer*>(user);
  const size_t bytes = size * n;
  long status = 0;
  curl_easy_getinfo(t->curl, CURLINFO_RESPONSE_CODE, &status);
  std::string& body = t->response->body;
  if (status >= 400) {
    // The message gives the status, not the body: only its start is kept, and an endless
    // one is not read on.
    if (body.size() >= kMaxErrorBodyBytes) {
      t->errorBodyCut = true;
      return 0;  // aborts the transfer
    }
    body.append(data, std::min(bytes, kMaxErrorBodyBytes - body.size()));
    return bytes;
  }
  if (t->sink && *t->sink) {
    char* type = nullptr;
    curl_easy_getinfo(t->curl, CURLINFO_CONTENT_TYPE, &type);
    try {
      (*t->sink)(data, bytes, type ? type : "");
    } catch (const std::exception& e) {
      t->sinkError = e.what();
      return 0;
    }
    return bytes;
  }
  if (body.size() + bytes > kMaxAnswerBytes) {
    t->sinkError = "the answer is larger than " + std::to_string(kMaxAnswerBytes >> 20) +
                   " MiB, more than a search or store answer needs: it may not be a DICOMweb "
                   "server; if it is, narrow the search";
    return 0;
  }
  body.append(data, bytes);
  return bytes;
}

int onProgress(void* user, curl_off_t, curl_off_t down, curl_off_t, curl_off_t up) {
  auto* t = static_cast<Transfer*>(user);
  if (t->cancel && t->cancel->load()) return 1;
  const auto now = std::chrono::steady_clock::now();
  if (down + up >= t->moved + kLeastProgressBytes) {
    t->moved = down + up;
    t->lastMove = now;
  } else if (now - t->lastMove >= std::chrono::seconds(t->timeoutSec)) {
    t->stalled = true;
    t->dripping = down + up > t->moved;
    return 1;
  }
  return 0;
}

std::string httpHint(long status, HttpService service) {
  if (service == HttpService::OmeZarr) {
    if (status == 401)
      return "the server wants credentials: give them in the URL "
             "(https://USER:PASSWORD@host/...; they are never shown)";
    if (status == 403) return "the server does not let these credentials read it";
    if (status == 404) return "not found: check the URL (it names the .ome.zarr folder)";
    if (status >= 500) return "the server failed; try again later or ask its administrator";
    return "the server refused the request; check the URL";
  }
  if (status == 401)
    return "the server wants credentials: set user and password (or bearerToken) for this node";
  if (status == 403) return "the credentials are not allowed to do this";
  if (status == 404) return "not found: check the node's base URL (e.g. .../dicom-web)";
  if (status >= 500) return "the server failed; try again later or ask its administrator";
  return "the server refused the request";
}

}  // namespace

HttpSession::HttpSession(PacsNode node, HttpService service)
    : node_(std::move(node)), service_(service), curl_(curl_easy_init()) {
  if (!curl_) throw inputError("Cannot start libcurl for " + node_.label());
  // libcurl opens the CA bundle and reads it to the end: a FIFO would block every request.
  struct stat st {};
  if (node_.caFile.empty()) return;
  const bool found = stat(node_.caFile.c_str(), &st) == 0;
  if (found && S_ISREG(st.st_mode)) return;
  curl_easy_cleanup(static_cast<CURL*>(curl_));
  throw inputError("DICOMweb " + node_.label() + ": its caFile " + node_.caFile +
                   (found ? " is not a regular file" : " cannot be read") +
                   ": give the path of a PEM file with the node's CA certificates in " +
                   pacsConfigPath());
}

HttpSession::~HttpSession() { curl_easy_cleanup(static_cast<CURL*>(curl_)); }

std::string HttpSession::escape(const std::string& value) {
  char* out = curl_easy_escape(static_cast<CURL*>(curl_), value.c_str(), int(value.size()));
  std::string escaped = out ? out : "";
  curl_free(out);
  // DICOM wildcards stay as typed: '*' is legal in a query (RFC 3986) and Orthanc's QIDO
  // matches an escaped %2A literally.
  std::string s;
  for (size_t i = 0; i < escaped.size(); ++i) {
    bool star = escaped.compare(i, 3, "%2A") == 0;
    s += star ? '*' : escaped[i];
    if (star) i += 2;
  }
  return s;
}

HttpResponse HttpSession::get(const std::string& url, const std::string& accept, const Sink& sink,
                              const std::atomic<bool>* cancel) {
  CURL* curl = static_cast<CURL*>(curl_);
  curl_easy_setopt(curl, CURLOPT_HTTPGET, 1L);
  return perform("GET", url, {"Accept: " + accept}, sink, cancel);
}

HttpResponse HttpSession::post(const std::string& url, const std::string& contentType,
                               const std::string& body, const std::string& accept,
                               const std::atomic<bool>* cancel) {
  CURL* curl = static_cast<CURL*>(curl_);
  curl_easy_setopt(curl, CURLOPT_POSTFIELDS, body.data());
  curl_easy_setopt(curl, CURLOPT_POSTFIELDSIZE_LARGE, curl_off_t(body.size()));
  return perform("POST", url, {"Content-Type: " + contentType, "Accept: " + accept}, {}, cancel);
}

HttpResponse HttpSession::perform(const std::string& what, const std::string& url,
                                  const std::vector<std::string>& headers, const Sink& sink,
                                  const std::atomic<bool>* cancel) {
  CURL* curl = static_cast<CURL*>(curl_);
  HttpResponse response;
  Transfer transfer{&sink, cancel, &response, curl, {}, node_.timeoutSec};
  curl_slist* list = nullptr;
  for (const auto& h : headers) list = curl_slist_append(list, h.c_str());
  char errorText[CURL_ERROR_SIZE] = {};
  curl_easy_setopt(curl, CURLOPT_URL, url.c_str());
  curl_easy_setopt(curl, CURLOPT_HTTPHEADER, list);
  curl_easy_setopt(curl, CURLOPT_ERRORBUFFER, errorText);
  curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, onBody);
  curl_easy_setopt(curl, CURLOPT_WRITEDATA, &transfer);
  curl_easy_setopt(curl, CURLOPT_NOPROGRESS, 0L);
  curl_easy_setopt(curl, CURLOPT_XFERINFOFUNCTION, onProgress);
  curl_easy_setopt(curl, CURLOPT_XFERINFODATA, &transfer);
  curl_easy_setopt(curl, CURLOPT_CONNECTTIMEOUT, long(node_.timeoutSec));
  // No byte for timeoutSec: the server has stopped (a large series may take long overall).
  curl_easy_setopt(curl, CURLOPT_LOW_SPEED_LIMIT, 1L);
  curl_easy_setopt(curl, CURLOPT_LOW_SPEED_TIME, long(node_.timeoutSec));
  curl_easy_setopt(curl, CURLOPT_BUFFERSIZE, 512L << 10);  // fewer, larger writes (a series)
  curl_easy_setopt(curl, CURLOPT_SSL_VERIFYPEER, 1L);
  curl_easy_setopt(curl, CURLOPT_SSL_VERIFYHOST, 2L);
  if (!node_.caFile.empty()) curl_easy_setopt(curl, CURLOPT_CAINFO, node_.caFile.c_str());
  if (!node_.bearerToken.empty()) {
    curl_easy_setopt(curl, CURLOPT_HTTPAUTH, CURLAUTH_BEARER);
    curl_easy_setopt(curl, CURLOPT_XOAUTH2_BEARER, node_.bearerToken.c_str());
  } else if (!node_.user.empty()) {
    curl_easy_setopt(curl, CURLOPT_HTTPAUTH, CURLAUTH_BASIC);
    curl_easy_setopt(curl, CURLOPT_USERNAME, node_.user.c_str());
    curl_easy_setopt(curl, CURLOPT_PASSWORD, node_.password.c_str());
  }
  lastStatus_ = 0;
  CURLcode code = curl_easy_perform(curl);
  curl_slist_free_all(list);
  curl_easy_setopt(curl, CURLOPT_HTTPHEADER, nullptr);
  curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &response.status);
  lastStatus_ = response.status;
  char* type = nullptr;
  curl_easy_getinfo(curl, CURLINFO_CONTENT_TYPE, &type);
  response.contentType = type ? type : "";
  const bool zarr = service_ == HttpService::OmeZarr;
  std::string where = (zarr ? "OME-Zarr " : "DICOMweb ") + what + " " + redactUrl(url);
  if (cancel && cancel->load())
    throw cancelledError(what == "POST" ? "Sending cancelled" : "Retrieval cancelled");
  if (!transfer.sinkError.empty()) throw inputError(where + ": " + transfer.sinkError);
  if (transfer.stalled && zarr)
    throw inputError(where + ": the server sent " +
                     (transfer.dripping ? "under " + std::to_string(kLeastProgressBytes) + " bytes"
                                        : std::string("nothing")) +
                     " for " + std::to_string(node_.timeoutSec) +
                     " s: it stopped answering; try again later");
  if (transfer.stalled)
    throw inputError(transfer.dripping ? drippingMessage(node_, what, kLeastProgressBytes)
                                       : stalledMessage(node_, what));
  if (code == CURLE_PEER_FAILED_VERIFICATION || code == CURLE_SSL_CACERT_BADFILE ||
      code == CURLE_SSL_CONNECT_ERROR || code == CURLE_SSL_CERTPROBLEM)
    throw inputError(where + ": TLS failed (" +
                     (*errorText ? errorText : curl_easy_strerror(code)) +
                     (zarr ? "): the server's certificate is not trusted; add its CA to the "
                             "system's (update-ca-certificates), or fix the server's certificate"
                           : "): the server's certificate is not trusted; give the node a caFile "
                             "with its CA, or fix the server's certificate"));
  if (transfer.errorBodyCut) code = CURLE_OK;  // the status says what failed
  if (code != CURLE_OK)
    throw inputError(
        where + ": " + (*errorText ? errorText : curl_easy_strerror(code)) +
        (code == CURLE_OPERATION_TIMEDOUT
             ? ": the server stopped answering (timeout " + std::to_string(node_.timeoutSec) + " s)"
         : code == CURLE_PARTIAL_FILE ? ": the server closed the connection "
                                        "before the end; try again"
         : zarr                       ? ": check the URL and the network"
                                      : ": check the node's URL and network"));
  if (response.status >= 400)
    throw inputError(where + ": HTTP " + std::to_string(response.status) + ": " +
                     httpHint(response.status, service_));
  return response;
}

}  // namespace voxray::pacs
