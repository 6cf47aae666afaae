#include <algorithm>
#include <cctype>
#include <cstdio>
#include <mutex>

#include "http_session.h"
#include "pacs_messages.h"
#include "voxray/io/error.h"
#include "voxray/io/zarr_url.h"

namespace voxray {
namespace {

bool startsWithNoCase(const std::string& s, const char* prefix) {
  const std::string p(prefix);
  return s.size() >= p.size() && std::equal(p.begin(), p.end(), s.begin(), [](char a, char b) {
           return std::tolower(uint8_t(a)) == std::tolower(uint8_t(b));
         });
}

// A key's bytes for a URL path: keys come from the metadata (a level's path may hold
// anything), so all but unreserved characters and '/' are percent-encoded; a '?' or '#' in a
// dataset path cannot start a query.
std::string escapeKey(const std::string& key) {
  std::string out;
  for (unsigned char c : key) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      out += char(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    }
  }
  return out;
}

class UrlStore final : public ZarrStore {
 public:
  UrlStore(std::string url, const std::atomic<bool>* cancel) : cancel_(cancel) {
    if (url.find_first_of("?#") != std::string::npos)
      throw inputError(pacs::redactUrl(url) +
                       ": an OME-Zarr URL names the .ome.zarr folder and has no query or "
                       "fragment (the chunks' names are appended to it); remove what follows "
                       "'?' or '#'");
    while (!url.empty() && url.back() == '/') url.pop_back();
    node_.transport = PacsNode::Transport::Web;
    node_.name = pacs::redactUrl(url);
    node_.baseUrl = url;
    base_ = std::move(url);
  }

  std::string where(const std::string& key) const override {
    return pacs::redactUrl(key.empty() ? base_ : base_ + "/" + escapeKey(key));
  }

  bool read(const std::string& key, std::vector<uint8_t>& data, uint64_t maxBytes,
            const std::string& tooLarge) override {
    data.clear();
    const auto sink = [&](const char* bytes, size_t n, const std::string&) {
      // Thrown here, it ends the transfer and comes back as "OME-Zarr GET URL: TOO_LARGE".
      if (data.size() + n > maxBytes) throw std::length_error(tooLarge);
      data.insert(data.end(), bytes, bytes + n);
    };
    std::unique_ptr<pacs::HttpSession> session = lease();
    long status = 0;
    try {
      status = session->get(base_ + "/" + escapeKey(key), "*/*", sink, cancel_).status;
    } catch (const Error& e) {
      const bool missing = e.kind() == Error::Kind::Input && session->lastStatus() == 404;
      giveBack(std::move(session));
      if (missing) return false;
      throw;
    }
    giveBack(std::move(session));
    // libcurl follows no redirect: one could take the credentials to another host.
    if (status != 200)
      throw inputError(
          "OME-Zarr GET " + where(key) + ": the server answered HTTP " + std::to_string(status) +
          (status >= 300 && status < 400
               ? " (a redirect, which Voxray does not follow): open the address it points to"
               : ", not the file (200): check the URL"));
    return true;
  }

 private:
  // One session (a libcurl handle and its connection) per reading thread: a handle serves one
  // transfer at a time, and a kept one reuses its connection for the next chunk.
  std::unique_ptr<pacs::HttpSession> lease() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (idle_.empty())
      return std::make_unique<pacs::HttpSession>(node_, pacs::HttpService::OmeZarr);
    std::unique_ptr<pacs::HttpSession> s = std::move(idle_.back());
    idle_.pop_back();
    return s;
  }
  void giveBack(std::unique_ptr<pacs::HttpSession> s) {
    std::lock_guard<std::mutex> lock(mutex_);
    idle_.push_back(std::move(s));
  }

  std::string base_;
  PacsNode node_;
  const std::atomic<bool>* cancel_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<pacs::HttpSession>> idle_;
};

void refuseFileOptions(const std::string& url, const LoadOptions& options) {
  const std::string where = pacs::redactUrl(url);
  if (options.raw)
    throw inputError(where + ": a URL is read as OME-Zarr; the --raw-* options do not apply");
  if (options.timePoint && *options.timePoint != 0)
    throw inputError(where + ": --time " + std::to_string(*options.timePoint) +
                     " is out of range: an OME-Zarr has 1 time point here");
}

}  // namespace

bool isUrl(const std::string& input) {
  return startsWithNoCase(input, "http://") || startsWithNoCase(input, "https://");
}

std::unique_ptr<ZarrStore> zarrUrlStore(const std::string& url, const std::atomic<bool>* cancel) {
  return std::make_unique<UrlStore>(url, cancel);
}

Volume loadVolumeOrUrl(const std::string& input, const LoadOptions& options) {
  if (!isUrl(input)) return loadVolume(input, options);
  refuseFileOptions(input, options);
#if defined(VOXRAY_HAS_ZARR)
  if (options.progress) options.progress(0.0, "Reading " + pacs::redactUrl(input));
  return importOmeZarr(*zarrUrlStore(input, options.cancel), options);
#else
  throw inputError(pacs::redactUrl(input) +
                   ": this build of Voxray cannot read OME-Zarr (it was built with "
                   "VOXRAY_WITH_ZARR=OFF)");
#endif
}

std::vector<Volume> loadVolumeSeriesOrUrl(const std::string& input, const LoadOptions& options) {
  if (!isUrl(input)) return loadVolumeSeries(input, options);
  LoadOptions first = options;
  first.timePoint.reset();
  std::vector<Volume> out;
  out.push_back(loadVolumeOrUrl(input, first));
  return out;
}

}  // namespace voxray
