// Retrieval benchmark (issue 12's closing note; not a test): the largest shared CT series from
// a local Orthanc over C-GET and WADO-RS, seconds to a ready volume (retrieved into a fresh
// cache and imported), against DCMTK's getscu and curl fetching the same series, in the same
// run. Usage: voxray_pacs_bench [REPEATS] (default 3; medians are printed).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "orthanc_server.h"
#include "voxray/io/load.h"
#include "voxray/io/pacs_cache.h"

namespace fs = std::filesystem;
using voxray::test::OrthancServer;

namespace {

const char* kSeries = "1.2.826.0.1.3680043.2.1125.1.75064541463040.2005072610384286453";
const char* kStudy = "1.2.826.0.1.3680043.2.1125.1.75064541463040.2005072610384286421";

double seconds(const std::function<void()>& f) {
  auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

uint64_t folderBytes(const std::string& folder) {
  uint64_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(folder))
    if (e.is_regular_file()) n += e.file_size();
  return n;
}

void shell(const std::string& command) {
  if (std::system(command.c_str()) != 0) {
    std::cerr << "failed: " << command << "\n";
    std::exit(1);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = argc > 1 ? std::atoi(argv[1]) : 3;
  OrthancServer server;
  int uploaded = server.upload(std::string(VOXRAY_DATA_DIR) + "/dicom/ct-visible-human-pelvis");
  std::cout << "ct-visible-human-pelvis: " << uploaded << " files uploaded\n";
  struct Row {
    std::string what;
    std::vector<double> s;
    uint64_t bytes = 0;
  };
  std::vector<Row> rows = {
      {"voxray C-GET, to ready volume", {}},  {"voxray C-GET, retrieval only", {}},
      {"getscu (DCMTK), to files", {}},       {"voxray WADO-RS, to ready volume", {}},
      {"voxray WADO-RS, retrieval only", {}}, {"curl WADO-RS, to one file", {}}};
  std::string area = voxray::test::tempFolder("bench");
  for (int r = 0; r < repeats; ++r) {
    // The raw tools first, Voxray after: neither profits from the other's warm caches more.
    std::string file = area + "/curl-" + std::to_string(r);
    rows[5].s.push_back(seconds([&] {
      shell("curl -sf -u " + std::string(OrthancServer::kUser) + ":" + OrthancServer::kPassword +
            " -H 'Accept: multipart/related; type=\"application/dicom\"; transfer-syntax=*' " +
            server.webNode().baseUrl + "/studies/" + kStudy + "/series/" + kSeries + " -o " + file);
    }));
    rows[5].bytes = fs::file_size(file);
    for (auto node : {server.dimseNode(), server.webNode()}) {
      bool web = node.transport == voxray::PacsNode::Transport::Web;
      std::string cache = area + "/cache-" + std::to_string(r) + (web ? "w" : "d");
      voxray::CachedSeries entry;
      double retrieve = 0;
      double ready = seconds([&] {
        voxray::PacsCache c(cache);
        auto client = voxray::makePacsClient(node);
        retrieve = seconds([&] { entry = c.retrieve(*client, kStudy, kSeries); });
        voxray::Volume v = voxray::loadVolume(entry.folder);
        if (v.dims.z != 150) std::exit(1);
      });
      rows[web ? 3 : 0].s.push_back(ready);
      rows[web ? 4 : 1].s.push_back(retrieve);
      rows[web ? 3 : 0].bytes = rows[web ? 4 : 1].bytes = entry.bytes;
    }
    std::string out = area + "/getscu-" + std::to_string(r);
    fs::create_directories(out);
    rows[2].s.push_back(seconds([&] {
      shell("getscu -aet VOXRAY -aec ORTHANC 127.0.0.1 " + std::to_string(server.dicomPort) +
            " -S -k QueryRetrieveLevel=SERIES -k StudyInstanceUID=" + kStudy +
            " -k SeriesInstanceUID=" + kSeries + " -od " + out);
    }));
    rows[2].bytes = folderBytes(out);
  }
  std::printf("%-34s %9s %9s %8s\n", "median of runs", "seconds", "MB", "MB/s");
  for (const auto& row : rows)
    std::printf("%-34s %9.3f %9.1f %8.1f\n", row.what.c_str(), median(row.s), row.bytes / 1e6,
                row.bytes / 1e6 / median(row.s));
  fs::remove_all(area);
  return 0;
}
