#include "pacs_messages.h"

#include <curl/curl.h>

#include <memory>

namespace voxray::pacs {
namespace {

const char* kHidden = "...";

// Each value of a query ("a=1&b" -> "a=...&..."): names stay, they say what was asked.
std::string hideValues(const std::string& query) {
  std::string out;
  size_t start = 0;
  while (start <= query.size()) {
    size_t end = query.find('&', start);
    if (end == std::string::npos) end = query.size();
    std::string item = query.substr(start, end - start);
    size_t eq = item.find('=');
    if (start > 0) out += '&';
    out += eq == std::string::npos ? kHidden : item.substr(0, eq + 1) + kHidden;
    start = end + 1;
  }
  return out;
}

// A text that libcurl does not take for a URL: everything after a '?' or '#' and before an
// '@' goes.
std::string redactRoughly(std::string url) {
  url = url.substr(0, url.find_first_of("?#"));
  size_t at = url.rfind('@');
  if (at == std::string::npos) return url;
  size_t scheme = url.find("://");
  return url.substr(0, scheme == std::string::npos ? 0 : scheme + 3) + url.substr(at + 1);
}

}  // namespace

std::string stalledMessage(const PacsNode& node, const std::string& what) {
  const std::string t = std::to_string(node.timeoutSec);
  return "PACS " + node.label() + ": " + what + ": the node sent nothing for " + t +
         " s (timeout " + t +
         " s): it stopped answering; try again later, or raise the node's timeout if it is "
         "slow";
}

std::string drippingMessage(const PacsNode& node, const std::string& what, long least) {
  const std::string t = std::to_string(node.timeoutSec);
  return "PACS " + node.label() + ": " + what + ": the node sent under " + std::to_string(least) +
         " bytes in " + t + " s (timeout " + t +
         " s): it is not answering at a usable rate; try again later, or raise the node's "
         "timeout if it is slow";
}

std::string unknownSeriesMessage(const PacsNode& node, const std::string& study,
                                 const std::string& series, bool studyKnown) {
  return "PACS " + node.label() +
         (studyKnown ? " has no series " + series + " in study " + study
                     : " has no study " + study) +
         ": check the UIDs (voxray-cli pacs find --level series --study UID lists a study's "
         "series)";
}

std::string redactUrl(const std::string& url) {
  std::unique_ptr<CURLU, void (*)(CURLU*)> u(curl_url(), curl_url_cleanup);
  if (!u ||
      curl_url_set(u.get(), CURLUPART_URL, url.c_str(), CURLU_NON_SUPPORT_SCHEME) != CURLUE_OK)
    return redactRoughly(url);
  curl_url_set(u.get(), CURLUPART_USER, nullptr, 0);
  curl_url_set(u.get(), CURLUPART_PASSWORD, nullptr, 0);
  curl_url_set(u.get(), CURLUPART_OPTIONS, nullptr, 0);
  char* query = nullptr;
  if (curl_url_get(u.get(), CURLUPART_QUERY, &query, 0) == CURLUE_OK && query) {
    std::string hidden = hideValues(query);
    curl_url_set(u.get(), CURLUPART_QUERY, hidden.c_str(), 0);
  }
  curl_free(query);
  char* fragment = nullptr;
  if (curl_url_get(u.get(), CURLUPART_FRAGMENT, &fragment, 0) == CURLUE_OK && fragment)
    curl_url_set(u.get(), CURLUPART_FRAGMENT, kHidden, 0);
  curl_free(fragment);
  char* out = nullptr;
  if (curl_url_get(u.get(), CURLUPART_URL, &out, 0) != CURLUE_OK || !out) return redactRoughly(url);
  std::string redacted = out;
  curl_free(out);
  return redacted;
}

}  // namespace voxray::pacs
