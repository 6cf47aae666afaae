// Retrieval benchmark (issue 12's closing note; not a test): one CT series from a local
// Orthanc over C-GET and WADO-RS, seconds to a ready volume (retrieved into a fresh cache and
// imported), against DCMTK's getscu and curl fetching the same series, in the same run; and
// a study-level C-FIND of the same store against DCMTK's findscu (dimse and both).
// Usage: voxray_pacs_bench [REPEATS [SERIES_FOLDER [web|web-overlap|web-folder|dimse|both]]]
// (defaults: 3, the shared pelvis CT, both; the 512x512x400 CT: docs/bench/make-ct400.sh
// OUT, then OUT/ct400). Medians are printed.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

#include "orthanc_server.h"
#include "voxray/io/dicom_import.h"
#include "voxray/io/load.h"
#include "voxray/io/pacs_cache.h"
#include "voxray/io/statistics.h"

namespace fs = std::filesystem;
using voxray::median;
using voxray::test::OrthancServer;

namespace {

// CPU seconds (user + system) of this process and its reaped children: Voxray's client
// during its steps, the raw tool (run through the shell) during its own; Orthanc, a child
// not reaped until the end, is in neither. Load on the shared machine stretches wall time
// far more than CPU time.
double cpuSeconds() {
  double total = 0;
  for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage u{};
    getrusage(who, &u);
    total += double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
             double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
  }
  return total;
}

double lastCpu = 0;  // the CPU seconds of the last seconds() call

double seconds(const std::function<void()>& f) {
  double cpu0 = cpuSeconds();
  auto t0 = std::chrono::steady_clock::now();
  f();
  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  lastCpu = cpuSeconds() - cpu0;
  return wall;
}

uint64_t folderBytes(const std::string& folder) {
  uint64_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(folder))
    if (e.is_regular_file()) n += e.file_size();
  return n;
}

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
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
  const std::string which = argc > 3 ? argv[3] : "both";
  std::string series =
      argc > 2 ? argv[2] : std::string(VOXRAY_DATA_DIR) + "/dicom/ct-visible-human-pelvis";
  // The UIDs and slice count to retrieve, from the files themselves.
  const voxray::Volume disk = voxray::loadVolume(series);
  const std::string studyUid = disk.study.studyInstanceUid,
                    seriesUid = disk.study.seriesInstanceUid;
  OrthancServer server;
  int uploaded = server.upload(series);
  std::cout << series << ": " << uploaded << " files uploaded; load average " << loadAverage()
            << "\n";
  struct Row {
    std::string what;
    std::vector<double> s, cpu;
    uint64_t bytes = 0;
  };
  std::vector<Row> rows;
  for (const char* what :
       {"voxray C-GET, to ready volume", "voxray C-GET, retrieval only", "getscu (DCMTK), to files",
        "voxray WADO-RS, to ready volume", "voxray WADO-RS, retrieval only",
        "curl WADO-RS, to one file", "voxray C-FIND, study level", "findscu (DCMTK), study level",
        "voxray WADO-RS, import after it", "WADO-RS, import not overlapped",
        "  of which the retrieval to files", "  of which the folder import"})
    rows.push_back(Row{what, {}, {}, 0});
  std::string area = voxray::test::tempFolder("bench");
  auto curl = [&](int r) {
    std::string file = area + "/curl-" + std::to_string(r);
    rows[5].s.push_back(seconds([&] {
      shell("curl -sf -u " + std::string(OrthancServer::kUser) + ":" + OrthancServer::kPassword +
            " -H 'Accept: multipart/related; type=\"application/dicom\"; transfer-syntax=*' " +
            server.webNode().baseUrl + "/studies/" + studyUid + "/series/" + seriesUid + " -o " +
            file);
    }));
    rows[5].cpu.push_back(lastCpu);
    rows[5].bytes = fs::file_size(file);
    fs::remove(file);
  };
  auto getscu = [&](int r) {
    std::string out = area + "/getscu-" + std::to_string(r);
    fs::create_directories(out);
    rows[2].s.push_back(seconds([&] {
      shell("getscu -aet VOXRAY -aec ORTHANC 127.0.0.1 " + std::to_string(server.dicomPort) +
            " -S -k QueryRetrieveLevel=SERIES -k StudyInstanceUID=" + studyUid +
            " -k SeriesInstanceUID=" + seriesUid + " -od " + out);
    }));
    rows[2].cpu.push_back(lastCpu);
    rows[2].bytes = folderBytes(out);
    fs::remove_all(out);
  };
  auto voxray = [&](int r, const voxray::PacsNode& node) {
    bool web = node.transport == voxray::PacsNode::Transport::Web;
    std::string cache = area + "/cache-" + std::to_string(r) + (web ? "w" : "d");
    voxray::CachedSeries entry;
    double retrieve = 0, retrieveCpu = 0;
    // The import reads and decodes each file as it arrives (DICOMweb; DIMSE files are read
    // after the transfer); what is left after the transfer is timed apart (web).
    double ready = seconds([&] {
      voxray::PacsCache c(cache);
      auto client = voxray::makePacsClient(node);
      voxray::DicomImport import;
      retrieve = seconds([&] { entry = c.retrieve(*client, studyUid, seriesUid, {}, &import); });
      retrieveCpu = lastCpu;
      double after = seconds([&] {
        voxray::Volume v = import.finish(entry.folder);
        if (v.dims != disk.dims) std::exit(1);
      });
      if (web) {
        rows[8].s.push_back(after);
        rows[8].cpu.push_back(lastCpu);
      }
    });
    rows[web ? 3 : 0].s.push_back(ready);
    rows[web ? 3 : 0].cpu.push_back(lastCpu);
    rows[web ? 4 : 1].s.push_back(retrieve);
    rows[web ? 4 : 1].cpu.push_back(retrieveCpu);
    rows[web ? 3 : 0].bytes = rows[web ? 4 : 1].bytes = entry.bytes;
    fs::remove_all(cache);
  };
  // Session 6's way, for the same run: the whole transfer, then the import from the files.
  auto voxrayThenImport = [&](int r) {
    std::string cache = area + "/cache-" + std::to_string(r) + "s";
    rows[9].s.push_back(seconds([&] {
      voxray::PacsCache c(cache);
      auto client = voxray::makePacsClient(server.webNode());
      voxray::CachedSeries entry;
      rows[10].s.push_back(seconds([&] { entry = c.retrieve(*client, studyUid, seriesUid); }));
      rows[10].cpu.push_back(lastCpu);
      rows[11].s.push_back(seconds([&] {
        voxray::Volume v = voxray::loadVolume(entry.folder);
        if (v.dims != disk.dims) std::exit(1);
      }));
      rows[11].cpu.push_back(lastCpu);
    }));
    rows[9].cpu.push_back(lastCpu);
    rows[9].bytes = rows[5].bytes;
    fs::remove_all(cache);
  };
  // The same study-level keys as Voxray's C-FIND (dimse_client.cpp), every study.
  auto findscu = [&](int) {
    std::string keys;
    for (const char* k :
         {"QueryRetrieveLevel=STUDY", "PatientName", "PatientID", "StudyDate", "StudyInstanceUID",
          "StudyDescription", "AccessionNumber", "ModalitiesInStudy", "NumberOfStudyRelatedSeries",
          "NumberOfStudyRelatedInstances"})
      keys += std::string(" -k ") + k;
    rows[7].s.push_back(seconds([&] {
      shell("findscu -S -aet VOXRAY -aec ORTHANC 127.0.0.1 " + std::to_string(server.dicomPort) +
            keys + " > /dev/null 2>&1");
    }));
    rows[7].cpu.push_back(lastCpu);
  };
  auto voxrayFind = [&](int) {
    size_t found = 0;
    rows[6].s.push_back(seconds([&] {
      found = voxray::makePacsClient(server.dimseNode())->find(voxray::PacsQuery{}).size();
    }));
    rows[6].cpu.push_back(lastCpu);
    if (found != 1) std::exit(1);  // the store holds the one study
  };
  // Each step's files go once it is timed: the runs before leave no page cache to reclaim
  // (the last runs were 2-6x slower, with 4x the CPU, while they stayed).
  // Each timed step starts with no dirty pages left by the one before (sync), and the raw
  // tool and Voxray take turns going first, so neither pays for the other's writes more.
  using Step = std::function<void(int)>;
  std::vector<std::pair<Step, Step>> pairs;
  if (which != "dimse" && which != "web-folder")
    pairs.push_back({curl, [&](int r) { voxray(r, server.webNode()); }});
  if (which != "dimse" && which != "web-overlap") pairs.push_back({curl, voxrayThenImport});
  if (which == "dimse" || which == "both")
    pairs.push_back({getscu, [&](int r) { voxray(r, server.dimseNode()); }});
  if (which == "dimse" || which == "both") pairs.push_back({findscu, voxrayFind});
  for (int r = 0; r < repeats; ++r)
    for (const auto& [raw, ours] : pairs)
      for (const Step& step : r % 2 ? std::vector<Step>{ours, raw} : std::vector<Step>{raw, ours}) {
        sync();
        step(r);
      }
  std::printf("%-34s %9s %9s %9s %8s\n", "median of runs", "seconds", "CPU s", "MB", "MB/s");
  for (const auto& row : rows) {
    if (row.s.empty()) continue;
    std::printf("%-34s %9.3f %9.3f", row.what.c_str(), median(row.s), median(row.cpu));
    if (row.bytes) std::printf(" %9.1f %8.1f", row.bytes / 1e6, row.bytes / 1e6 / median(row.s));
    std::printf("\n");
  }
  // Ratios of medians, and every run (the machine is shared: the spread matters).
  auto ratio = [&](size_t ours, size_t raw, const char* what) {
    if (!rows[ours].s.empty() && !rows[raw].s.empty())
      std::printf("%-34s %8.2fx %8.2fx (wall, CPU)\n", what,
                  median(rows[ours].s) / median(rows[raw].s),
                  median(rows[ours].cpu) / median(rows[raw].cpu));
  };
  ratio(0, 2, "C-GET ready volume / getscu");
  ratio(1, 2, "C-GET retrieval / getscu");
  ratio(3, 5, "WADO-RS ready volume / curl");
  ratio(4, 5, "WADO-RS retrieval / curl");
  ratio(9, 5, "WADO-RS not overlapped / curl");
  ratio(6, 7, "C-FIND / findscu");
  for (const auto& row : rows) {
    if (row.s.empty()) continue;
    std::printf("runs: %-28s", row.what.c_str());
    for (size_t i = 0; i < row.s.size(); ++i) std::printf(" %.3f/%.3f", row.s[i], row.cpu[i]);
    std::printf("  (wall/CPU s)\n");
  }
  std::printf("load average at the end: %s\n", loadAverage().c_str());
  fs::remove_all(area);
  return 0;
}
