#include "orthanc_server.h"

#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <curl/curl.h>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace voxray::test {
namespace {

const char* kOrthanc = "/usr/sbin/Orthanc";
const char* kDicomWebPlugin = "/usr/share/orthanc/plugins/libOrthancDicomWeb.so";

size_t appendBody(char* data, size_t size, size_t n, void* out) {
  static_cast<std::string*>(out)->append(data, size * n);
  return size * n;
}

// One request to the REST API; returns the HTTP status (0: no connection) and fills BODY.
long request(int port, const std::string& path, const std::string* upload, std::string& body) {
  CURL* curl = curl_easy_init();
  std::string url = "http://127.0.0.1:" + std::to_string(port) + path;
  std::string auth = std::string(OrthancServer::kUser) + ":" + OrthancServer::kPassword;
  curl_easy_setopt(curl, CURLOPT_URL, url.c_str());
  curl_easy_setopt(curl, CURLOPT_USERPWD, auth.c_str());
  curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, appendBody);
  curl_easy_setopt(curl, CURLOPT_WRITEDATA, &body);
  curl_easy_setopt(curl, CURLOPT_TIMEOUT, 60L);
  if (upload) {
    curl_easy_setopt(curl, CURLOPT_POSTFIELDS, upload->data());
    curl_easy_setopt(curl, CURLOPT_POSTFIELDSIZE_LARGE, curl_off_t(upload->size()));
  }
  long status = 0;
  if (curl_easy_perform(curl) == CURLE_OK) curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &status);
  curl_easy_cleanup(curl);
  return status;
}

bool isDicomFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  char magic[4] = {};
  in.seekg(128);
  return in.read(magic, 4) && std::string(magic, 4) == "DICM";
}

// A DICOMDIR (the Philips folders' DIRFILE) is an index, not an instance to store.
bool isDicomdir(const fs::path& p) {
  std::string name = p.filename().string();
  return name == "DIRFILE" || name == "DICOMDIR";
}

}  // namespace

int loopbackSocket(int& port, bool listening) {
  int s = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t len = sizeof addr;
  if (bind(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
      (listening && listen(s, 4) != 0) ||
      getsockname(s, reinterpret_cast<sockaddr*>(&addr), &len) != 0) {
    close(s);
    throw std::runtime_error("no free TCP port on 127.0.0.1");
  }
  port = ntohs(addr.sin_port);
  return s;
}

int freePort() {
  int port = 0;
  close(loopbackSocket(port, false));
  return port;
}

std::string tempFolder(const std::string& tag) {
  fs::create_directories(VOXRAY_TEST_TMP);
  std::string pattern = std::string(VOXRAY_TEST_TMP) + "/" + tag + "-XXXXXX";
  if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create " + pattern);
  return pattern;
}

OrthancServer::OrthancServer() {
  if (access(kOrthanc, X_OK) != 0 || access(kDicomWebPlugin, R_OK) != 0)
    throw std::runtime_error(std::string("Orthanc is not installed (") + kOrthanc + ", " +
                             kDicomWebPlugin + "): run scripts/bootstrap");
  folder = tempFolder("orthanc");
  httpPort = freePort();
  dicomPort = freePort();
  movePort = freePort();
  nlohmann::json config = {{"Name", "voxray-test"},
                           {"StorageDirectory", folder + "/storage"},
                           {"IndexDirectory", folder + "/storage"},
                           {"HttpPort", httpPort},
                           {"DicomPort", dicomPort},
                           {"DicomAet", kAe},
                           {"DicomCheckCalledAet", true},
                           {"RemoteAccessAllowed", false},
                           {"AuthenticationEnabled", true},
                           {"RegisteredUsers", {{kUser, kPassword}}},
                           {"DicomModalities", {{"voxray", {"VOXRAY", "127.0.0.1", movePort}}}},
                           // Orthanc 1.10 has no option for the listening address (its
                           // sockets take every interface), so it serves only loopback:
                           // HTTP by RemoteAccessAllowed, DIMSE to the one modality known,
                           // VOXRAY at 127.0.0.1 (its host checked).
                           {"DicomCheckModalityHost", true},
                           {"DicomAlwaysAllowEcho", false},
                           {"DicomAlwaysAllowStore", false},
                           {"DicomAlwaysAllowFind", false},
                           {"DicomAlwaysAllowGet", false},
                           {"DicomAlwaysAllowMove", false},
                           {"SaveJobs", false},
                           {"StableAge", 1},
                           {"Plugins", {kDicomWebPlugin}},
                           {"DicomWeb", {{"Enable", true}, {"Root", "/dicom-web/"}}}};
  std::ofstream(folder + "/orthanc.json") << config.dump(2);
  std::string logPath = folder + "/orthanc.log";
  pid_ = fork();
  if (pid_ == 0) {
    freopen(logPath.c_str(), "w", stdout);
    freopen(logPath.c_str(), "a", stderr);
    std::string configPath = folder + "/orthanc.json";
    execl(kOrthanc, kOrthanc, "--no-jobs", configPath.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  std::string body;
  while (request(httpPort, "/system", nullptr, body) != 200) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_ || std::chrono::steady_clock::now() > deadline) {
      std::string why = "Orthanc did not start on ports " + std::to_string(httpPort) + "/" +
                        std::to_string(dicomPort) + "; its log:\n" + log();
      stop();
      throw std::runtime_error(why);
    }
    body.clear();
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

OrthancServer::~OrthancServer() {
  stop();
  std::error_code ignored;
  fs::remove_all(folder, ignored);
}

void OrthancServer::stop(int signal) {
  if (pid_ <= 0) return;
  kill(pid_, signal);
  kill(pid_, SIGCONT);  // a frozen server gets the signal only once it runs
  int status = 0;
  waitpid(pid_, &status, 0);
  pid_ = -1;
}

void OrthancServer::freeze() {
  if (pid_ > 0) kill(pid_, SIGSTOP);
}

void OrthancServer::thaw() {
  if (pid_ > 0) kill(pid_, SIGCONT);
}

std::string OrthancServer::log() const {
  std::ifstream in(folder + "/orthanc.log");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int OrthancServer::upload(const std::string& path) {
  std::vector<fs::path> files;
  if (fs::is_directory(path)) {
    for (const auto& e : fs::recursive_directory_iterator(path))
      if (e.is_regular_file() && isDicomFile(e.path()) && !isDicomdir(e.path()))
        files.push_back(e.path());
  } else {
    files.push_back(path);
  }
  // Several uploads at once: Orthanc stores them in parallel (10,000 tiny studies in seconds).
  std::atomic<size_t> next{0};
  std::mutex mutex;
  std::string error;
  auto worker = [&] {
    for (size_t i = next++; i < files.size(); i = next++) {
      std::ifstream in(files[i], std::ios::binary);
      std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::string body;
      if (request(httpPort, "/instances", &data, body) != 200) {
        std::lock_guard<std::mutex> lock(mutex);
        error = "Orthanc refused " + files[i].string() + ": " + body;
        next = files.size();
      }
    }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t) threads.emplace_back(worker);
  for (auto& t : threads) t.join();
  if (!error.empty()) throw std::runtime_error(error);
  return int(files.size());
}

std::string OrthancServer::get(const std::string& path) const {
  std::string body;
  long status = request(httpPort, path, nullptr, body);
  if (status >= 400 || status == 0)
    throw std::runtime_error("GET " + path + ": HTTP " + std::to_string(status) + " " + body);
  return body;
}

PacsNode OrthancServer::dimseNode() const {
  PacsNode node =
      parsePacsNode("dicom://" + std::string(kAe) + "@127.0.0.1:" + std::to_string(dicomPort));
  node.timeoutSec = 10;
  return node;
}

PacsNode OrthancServer::moveNode() const {
  PacsNode node = dimseNode();
  node.receivePort = movePort;
  return node;
}

PacsNode OrthancServer::webNode() const {
  PacsNode node = parsePacsNode("http://127.0.0.1:" + std::to_string(httpPort) + "/dicom-web");
  node.user = kUser;
  node.password = kPassword;
  node.timeoutSec = 10;
  return node;
}

}  // namespace voxray::test
