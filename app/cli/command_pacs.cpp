// voxray-cli pacs echo|find|get|send NODE ...: the PACS client, scriptable. NODE is a name
// from the node configuration or an address (dicom://AE@host:port, http(s)://host/path).
// Patient names and IDs are printed only with --show-patient.
#include <malloc.h>
#include <sys/prctl.h>

#include <chrono>
#include <iostream>
#include <optional>

#include "commands.h"
#include "info_json.h"
#include "json_text.h"
#include "progress.h"
#include "terminal_text.h"
#include "voxray/io/error.h"

#ifdef VOXRAY_HAS_DICOM  // lean builds (VOXRAY_WITH_DICOM=OFF) have no PACS client
#include "voxray/io/dicom_import.h"
#include "voxray/io/load.h"
#include "voxray/io/pacs.h"
#include "voxray/io/pacs_cache.h"
#include "voxray/studydb/study_db.h"

namespace voxray::cli {
namespace {

struct PacsOptions {
  std::string node;
  bool json = false;
  bool showPatient = false;
  bool noOpen = false;
  PacsQuery query;
  std::string level = "study", dates, study, series, cacheDir, db;
  std::vector<std::string> files;
};

// A count the node did not give (or gave as no whole number: PacsMatch keeps 0) is null.
nlohmann::json count(int n) { return n > 0 ? nlohmann::json(n) : nlohmann::json(); }

// A series-level match is one series: its number, not a count of series.
nlohmann::json matchJson(const PacsMatch& m, QueryLevel level, bool showPatient) {
  nlohmann::json j = {{"study_uid", m.studyInstanceUid},   {"study_date", m.studyDate},
                      {"description", m.studyDescription}, {"accession", m.accessionNumber},
                      {"modalities", m.modalities},        {"images", count(m.numberOfInstances)}};
  if (level == QueryLevel::Series) {
    j["series_uid"] = m.seriesInstanceUid;
    j["series_number"] = m.seriesNumber;
    j["series_description"] = m.seriesDescription;
  } else {
    j["series"] = count(m.numberOfSeries);
  }
  if (showPatient) {
    j["patient_name"] = m.patientName;
    j["patient_id"] = m.patientId;
  }
  return j;
}

int runFind(const PacsOptions& o) {
  PacsQuery q = o.query;
  q.level = o.level == "series" ? QueryLevel::Series : QueryLevel::Study;
  q.studyInstanceUid = o.study;
  if (!o.dates.empty()) {
    size_t dash = o.dates.find('-');
    q.dateFrom = o.dates.substr(0, dash);
    q.dateTo = dash == std::string::npos ? q.dateFrom : o.dates.substr(dash + 1);
  }
  // Text is printed page by page as the node answers (a search with 10,000 matches shows
  // its first ones at once); JSON is one array at the end.
  // Every string from the node goes through terminalText: it may hold terminal controls.
  const bool series = q.level == QueryLevel::Series;
  auto line = [&](const PacsMatch& m) {
    auto number = [](int n) { return n > 0 ? std::to_string(n) : std::string("?"); };
    std::cout << terminalText(m.studyDate) << "  " << terminalText(m.modalities) << "  ";
    if (series)
      std::cout << "#" << m.seriesNumber << "  ";
    else
      std::cout << number(m.numberOfSeries) << " series  ";
    std::cout << number(m.numberOfInstances) << " images  "
              << terminalText(series ? m.seriesInstanceUid : m.studyInstanceUid) << "  "
              << terminalText(series ? m.seriesDescription : m.studyDescription);
    if (o.showPatient) std::cout << "  " << terminalText(m.patientName);
    std::cout << "\n";
  };
  FindOptions options;
  nlohmann::json list = nlohmann::json::array();
  options.page = [&](const std::vector<PacsMatch>& page) {
    for (const auto& m : page) {
      list.push_back(matchJson(m, q.level, o.showPatient));
      if (!o.json) line(m);
    }
    if (!o.json) std::cout.flush();
  };
  FindResult result = makePacsClient(resolvePacsNode(o.node))->findPages(q, options);
  if (o.json) std::cout << jsonText(list) << "\n";
  if (series && result.matches.empty())
    std::cerr << "no series matched in study " << terminalText(q.studyInstanceUid)
              << ": check the Study Instance UID (pacs find without --level series lists "
                 "studies)\n";
  if (result.more)
    std::cerr << "more: the node holds more than " << result.matches.size()
              << " matches; narrow the search, raise --limit or page with --offset\n";
  return 0;
}

int runGet(const PacsOptions& o) {
  if (o.study.empty() || o.series.empty())
    throw inputError("pacs get needs --study UID and --series UID (find them with pacs find)");
  // The half-megabyte images pass through memory that glibc, left to itself, hands back to
  // the kernel and takes again image by image (its dynamic thresholds): fresh pages each
  // time, zeroed by the kernel. Kept instead: on a loaded 2-core Xeon, 8,000 instead of
  // 13,000-21,000 page faults and 0.2 s instead of 0.3-0.9 s of system time for 400 CT
  // images (issue 39 item 8). Volumes are not malloc's (voxel_memory.h).
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  // No transparent huge pages for the volume: they speed up the raycaster's gathers, and
  // this command renders nothing, while taking them (voxel_memory.h marks volumes for them)
  // stalled in the kernel's compaction on the shared, loaded Xeon: 0.29-0.82 s of system
  // time with them, 0.20-0.28 s without, for the same 400 images.
  prctl(PR_SET_THP_DISABLE, 1, 0, 0, 0);
  auto client = makePacsClient(resolvePacsNode(o.node));
  PacsCache cache(o.cacheDir.empty() ? defaultPacsCacheFolder() : o.cacheDir);
  auto report = terminalProgress("Retrieving");
  RetrieveOptions options;
  options.progress = [&](const RetrieveProgress& p) {
    if (report)
      report(p.total > 0 ? double(p.received) / p.total : 0.0,
             std::to_string(p.received) + " images");
  };
  auto start = std::chrono::steady_clock::now();
  // The volume is decoded as the images arrive (DicomImport, on its own thread while the
  // transfer runs), not read back from the cache's files after it: issue 39 item 8, the
  // whole process within 1.2x curl's transfer.
  LoadOptions load;
  load.series = o.series;
  std::optional<DicomImport> import;
  if (!o.noOpen) import.emplace(load);
  CachedSeries entry =
      cache.retrieve(*client, o.study, o.series, options, import ? &*import : nullptr);
  auto retrieved = std::chrono::steady_clock::now();
  std::optional<ImportReport> stored;
  std::string dbFolder;
  if (!o.db.empty()) {
    // Copied: the cache evicts, the database keeps what it was given.
    StudyDb db(o.db);
    ImportOptions copy;
    copy.copy = true;
    stored = db.import({entry.folder}, copy);
    dbFolder = db.folder();
  }
  double retrieveS = std::chrono::duration<double>(retrieved - start).count();
  // --no-open: the series is in the cache, nothing is decoded (a prefetch).
  std::optional<Volume> v;
  if (import) v = import->finish(entry.folder);
  double readyS = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json j = v ? infoJson(*v, nullptr, import->storedRange()) : nlohmann::json::object();
  j["cache_folder"] = entry.folder;
  j["images"] = entry.images;
  j["megabytes"] = double(entry.bytes) / 1e6;
  j["retrieve_s"] = retrieveS;
  if (v) j["ready_s"] = readyS;
  j["mb_per_s"] = double(entry.bytes) / 1e6 / readyS;
  if (stored) {
    j["study_db"] = dbFolder;
    j["study_db_instances"] = stored->added + stored->updated;
  }
  if (o.json) {
    std::cout << jsonText(j) << "\n";
    return 0;
  }
  std::cout << "cached      " << terminalText(entry.folder) << " (" << entry.images << " images, "
            << double(entry.bytes) / 1e6 << " MB)\n";
  if (v)
    std::cout << "dims        " << v->dims.x << " x " << v->dims.y << " x " << v->dims.z << "\n"
              << "ready in    " << readyS << " s (retrieval " << retrieveS << " s, "
              << j["mb_per_s"].get<double>() << " MB/s)\n";
  else
    std::cout << "retrieved in " << retrieveS << " s (" << j["mb_per_s"].get<double>()
              << " MB/s)\n";
  if (stored)
    std::cout << "stored      " << stored->added + stored->updated << " images in the study "
              << "database " << terminalText(dbFolder) << "\n";
  return 0;
}

}  // namespace

Run addPacsCommand(CLI::App& app) {
  auto* pacs = app.add_subcommand("pacs", "Search, retrieve and send studies (DIMSE, DICOMweb)");
  pacs->require_subcommand(1);
  auto o = std::make_shared<PacsOptions>();
  auto nodeHelp = "node name from " + pacsConfigPath() +
                  ", or dicom://AE@host:port, or http(s)://host/dicom-web";
  auto* echo = pacs->add_subcommand("echo", "Check that a node answers (C-ECHO; QIDO-RS)");
  auto* find = pacs->add_subcommand("find", "Search studies (or the series of one study)");
  auto* get = pacs->add_subcommand("get", "Retrieve a series into the cache and open it");
  auto* send = pacs->add_subcommand("send", "Send DICOM files (C-STORE; STOW-RS)");
  for (auto* cmd : {echo, find, get, send}) {
    cmd->add_option("NODE", o->node, nodeHelp)->required();
    cmd->add_flag("--json", o->json, "machine-readable output on stdout");
  }
  find->add_option("--name", o->query.patientName, "patient name (wildcards * ?)");
  find->add_option("--id", o->query.patientId, "patient ID");
  find->add_option("--date", o->dates, "study date YYYYMMDD or range FROM-TO");
  find->add_option("--modality", o->query.modality, "modality (CT, MR, ...)");
  find->add_option("--accession", o->query.accessionNumber, "accession number");
  find->add_option("--level", o->level, "study or series (series needs --study)")
      ->check(CLI::IsMember({"study", "series"}));
  find->add_option("--study", o->study, "Study Instance UID (series level)");
  find->add_option("--limit", o->query.limit, "at most this many matches");
  find->add_option("--offset", o->query.offset, "skip this many (DICOMweb paging)");
  find->add_flag("--show-patient", o->showPatient, "print patient names and IDs");
  get->add_option("--study", o->study, "Study Instance UID")->required();
  get->add_option("--series", o->series, "Series Instance UID")->required();
  get->add_option("--cache", o->cacheDir,
                  "cache folder (default " + defaultPacsCacheFolder() + ")");
  get->add_option("--db", o->db,
                  "also store the series in this study database (copied; voxray-cli db find "
                  "finds it next time)");
  get->add_flag("--no-open", o->noOpen,
                "only retrieve the series into the cache (no volume is decoded or reported)");
  send->add_option("FILES", o->files, "DICOM files to send")->required();
  return [o, echo, find, get] {
    if (echo->parsed()) {
      PacsNode node = resolvePacsNode(o->node);
      makePacsClient(node)->echo();
      if (o->json)
        std::cout << jsonText({{"node", node.label()}, {"ok", true}}) << "\n";
      else
        std::cout << terminalText(node.label()) << " answers\n";
      return 0;
    }
    if (find->parsed()) return runFind(*o);
    if (get->parsed()) return runGet(*o);
    makePacsClient(resolvePacsNode(o->node))->store(o->files);
    if (o->json)
      std::cout << jsonText({{"sent", o->files.size()}}) << "\n";
    else
      std::cout << "sent " << o->files.size() << " files\n";
    return 0;
  };
}

}  // namespace voxray::cli
#else
namespace voxray::cli {
Run addPacsCommand(CLI::App& app) {
  app.add_subcommand("pacs", "PACS client (not in this build)")->allow_extras();
  return []() -> int { throw inputError("this voxray-cli was built without DICOM and PACS"); };
}
}  // namespace voxray::cli
#endif
