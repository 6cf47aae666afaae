// voxray-cli db import|find|series|priors|delete|verify: the local study database (issue 37),
// scriptable. Patient names and IDs appear in find's and priors' output (the user asked for
// the patient) and nowhere else: not in messages, not on stderr.
#include <iostream>
#include <memory>

#include "commands.h"
#include "json_text.h"
#include "progress.h"
#include "terminal_text.h"
#include "voxray/io/error.h"

#ifdef VOXRAY_HAS_STUDYDB
#include "voxray/io/pacs_cache.h"
#include "voxray/studydb/study_db.h"

namespace voxray::cli {
namespace {

struct DbOptions {
  std::string db, study, series, dates, cacheDir;
  std::vector<std::string> paths;
  StudyQuery query;
  bool json = false, copy = false, pacsCache = false, rebuild = false;
};

// The database, saying on stderr when its file was damaged and has been made again.
std::unique_ptr<StudyDb> openDb(const std::string& folder) {
  auto db = std::make_unique<StudyDb>(folder);
  if (db->rebuiltOnOpen())
    std::cerr << "the study database file in " << terminalText(db->folder())
              << " was damaged: rebuilt from its journal (imports.jsonl)\n";
  return db;
}

nlohmann::json studyJson(const StudyRow& r) {
  return {{"patient_name", r.patient.name},
          {"patient_id", r.patient.patientId},
          {"birth_date", r.patient.birthDate},
          {"sex", r.patient.sex},
          {"study_uid", r.study.uid},
          {"date", r.study.date},
          {"time", r.study.time},
          {"description", r.study.description},
          {"accession", r.study.accession},
          {"study_id", r.study.studyId},
          {"modalities", r.modalities},
          {"series", r.seriesCount},
          {"images", r.instanceCount}};
}

void printStudies(const std::vector<StudyRow>& rows, bool json, const char* none) {
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& r : rows) list.push_back(studyJson(r));
    std::cout << jsonText(list) << "\n";
    return;
  }
  if (rows.empty()) std::cerr << none << "\n";
  for (const auto& r : rows)
    std::cout << terminalText(r.study.date.empty() ? "--------" : r.study.date) << "  "
              << terminalText(r.modalities) << "  " << r.seriesCount << " series  "
              << r.instanceCount << " images  " << terminalText(r.study.uid) << "  "
              << terminalText(r.study.description) << "  " << terminalText(r.patient.name) << " ("
              << terminalText(r.patient.patientId) << ")\n";
}

int runImport(const DbOptions& o) {
  if (o.paths.empty() && !o.pacsCache)
    throw inputError("db import needs folders or files to import (or --pacs-cache)");
  auto opened = openDb(o.db);
  StudyDb& db = *opened;
  ImportOptions options;
  std::vector<std::string> paths = o.paths;
  if (o.pacsCache) {
    // Retrievals are evicted from the cache: the database keeps copies of its own.
    PacsCache cache(o.cacheDir.empty() ? defaultPacsCacheFolder() : o.cacheDir);
    for (const auto& s : cache.entries()) paths.push_back(s.folder);
    if (paths.empty()) {
      std::cerr << "the PACS cache " << terminalText(cache.root()) << " holds no series\n";
      return 0;
    }
    options.copy = true;
  }
  options.copy = options.copy || o.copy;
  auto report = terminalProgress("Importing");
  if (report)
    options.progress = [&](int done, int total) {
      report(total > 0 ? double(done) / total : 1.0, std::to_string(done) + " files");
    };
  ImportReport r = db.import(paths, options);
  for (const auto& w : r.warnings) std::cerr << "warning: " << terminalText(w) << "\n";
  if (o.json) {
    nlohmann::json skipped = nlohmann::json::array();
    for (const auto& s : r.skipped) skipped.push_back({{"path", s.path}, {"reason", s.reason}});
    std::cout << jsonText({{"database", db.folder()},
                           {"files", r.filesScanned},
                           {"added", r.added},
                           {"updated", r.updated},
                           {"unchanged", r.unchanged},
                           {"not_dicom", r.notDicom},
                           {"skipped", skipped},
                           {"warnings", r.warnings},
                           {"studies", r.studyUids},
                           {"series", r.seriesUids}})
              << "\n";
    return 0;
  }
  std::cout << "imported " << r.added + r.updated << " instances (" << r.added << " new, "
            << r.updated << " read again, " << r.unchanged << " unchanged) of "
            << r.studyUids.size() << " studies, " << r.seriesUids.size() << " series from "
            << r.filesScanned << " files into " << terminalText(db.folder()) << "\n";
  if (!r.skipped.empty()) {
    std::cout << "skipped " << r.skipped.size() << " files (" << r.notDicom << " not DICOM):\n";
    // The first ones with their reasons; 10,000 stray files need not scroll the terminal.
    const size_t shown = std::min<size_t>(r.skipped.size(), 20);
    for (size_t i = 0; i < shown; ++i)
      std::cout << "  " << terminalText(r.skipped[i].path) << ": "
                << terminalText(r.skipped[i].reason) << "\n";
    if (shown < r.skipped.size())
      std::cout << "  ... and " << r.skipped.size() - shown << " more (--json lists all)\n";
  }
  return 0;
}

int runSeries(const DbOptions& o) {
  auto opened = openDb(o.db);
  StudyDb& db = *opened;
  if (db.study(o.study).empty())
    throw inputError("Study " + o.study + " is not in the study database " + db.folder() +
                     ": find its UID with voxray-cli db find");
  auto rows = db.series(o.study);
  if (o.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& r : rows)
      list.push_back({{"series_uid", r.series.uid},
                      {"number", r.series.number},
                      {"description", r.series.description},
                      {"modality", r.series.modality},
                      {"body_part", r.series.bodyPart},
                      {"images", r.instanceCount},
                      {"frames", r.frameCount},
                      {"missing", r.missing},
                      {"changed", r.changed}});
    std::cout << jsonText(list) << "\n";
    return 0;
  }
  for (const auto& r : rows) {
    std::cout << "#" << r.series.number << "  " << terminalText(r.series.modality) << "  "
              << terminalText(r.series.bodyPart.empty() ? "-" : r.series.bodyPart) << "  "
              << r.instanceCount << " images  db:" << terminalText(r.series.uid) << "  "
              << terminalText(r.series.description);
    if (r.missing > 0) std::cout << "  (" << r.missing << " missing)";
    if (r.changed > 0) std::cout << "  (" << r.changed << " changed)";
    std::cout << "\n";
  }
  return 0;
}

int runDelete(const DbOptions& o) {
  if (o.study.empty() == o.series.empty())
    throw inputError("db delete needs a STUDY_UID or --series SERIES_UID (one of them)");
  auto opened = openDb(o.db);
  StudyDb& db = *opened;
  int n = o.study.empty() ? db.deleteSeries(o.series) : db.deleteStudy(o.study);
  const std::string& uid = o.study.empty() ? o.series : o.study;
  if (n == 0)
    throw inputError((o.study.empty() ? "Series " : "Study ") + uid +
                     " is not in the study database " + db.folder() +
                     ": find its UID with voxray-cli db find / db series");
  if (o.json)
    std::cout << jsonText({{"deleted", uid}, {"instances", n}}) << "\n";
  else
    std::cout << "deleted " << terminalText(uid) << " (" << n
              << " instances; files outside the database were left where they are)\n";
  return 0;
}

int runVerify(const DbOptions& o) {
  StudyDb db(o.db);
  if (db.rebuiltOnOpen()) std::cerr << "the database file was damaged: rebuilt from its journal\n";
  if (o.rebuild) db.rebuild();
  VerifyReport r = db.verify();
  r.rebuilt = o.rebuild || db.rebuiltOnOpen();
  if (o.json) {
    std::cout << jsonText({{"checked", r.checked},
                           {"ok", r.ok},
                           {"missing", r.missing},
                           {"changed", r.changed},
                           {"rebuilt", r.rebuilt},
                           {"studies", db.studyCount()}})
              << "\n";
  } else {
    if (o.rebuild) std::cout << "rebuilt from the journal: " << db.studyCount() << " studies\n";
    std::cout << "checked " << r.checked << " files: " << r.ok << " ok, " << r.missing.size()
              << " missing, " << r.changed.size() << " changed\n";
    for (const auto& p : r.missing) std::cout << "  missing  " << terminalText(p) << "\n";
    for (const auto& p : r.changed) std::cout << "  changed  " << terminalText(p) << "\n";
  }
  // Missing or changed files are what verify is asked to find, not a failure of it.
  return 0;
}

}  // namespace

Run addDbCommand(CLI::App& app) {
  auto* db = app.add_subcommand("db", "The local study database: import, search, priors");
  db->require_subcommand(1);
  auto o = std::make_shared<DbOptions>();
  auto* import = db->add_subcommand("import", "Index DICOM folders and files (headers only)");
  auto* find = db->add_subcommand("find", "Search studies");
  auto* series = db->add_subcommand("series", "List a study's series (open one as db:UID)");
  auto* priors = db->add_subcommand("priors", "The same patient's earlier studies");
  auto* del = db->add_subcommand("delete", "Remove a study or series from the database");
  auto* verify = db->add_subcommand("verify", "Find files that are missing or changed");
  for (auto* cmd : {import, find, series, priors, del, verify}) {
    cmd->add_option("--db", o->db, "database folder (default " + defaultStudyDbFolder() + ")")
        ->default_str(defaultStudyDbFolder());
    cmd->add_flag("--json", o->json, "machine-readable output on stdout");
  }
  o->db = defaultStudyDbFolder();
  import->add_option("PATHS", o->paths, "folders (searched recursively), files or DICOMDIRs");
  import->add_flag("--copy", o->copy, "copy the files into the database (default: refer to them)");
  import->add_flag("--pacs-cache", o->pacsCache,
                   "also import every series of the PACS cache (copied: the cache evicts)");
  import->add_option("--cache", o->cacheDir,
                     "PACS cache folder (default " + defaultPacsCacheFolder() + ")");
  find->add_option("--patient", o->query.patientName, "patient name, any part (wildcards * ?)");
  find->add_option("--id", o->query.patientId, "patient ID (wildcards * ?)");
  find->add_option("--date", o->dates,
                   "study date YYYYMMDD or range FROM-TO (either may be empty)");
  find->add_option("--modality", o->query.modality, "a series of this modality (CT, MR, ...)");
  find->add_option("--description", o->query.description, "part of a study or series description");
  find->add_option("--limit", o->query.limit, "at most this many studies");
  series->add_option("STUDY_UID", o->study, "Study Instance UID")->required();
  priors->add_option("STUDY_UID", o->study, "Study Instance UID")->required();
  del->add_option("STUDY_UID", o->study, "Study Instance UID");
  del->add_option("--series", o->series, "delete only this series");
  verify->add_flag("--rebuild", o->rebuild, "first make the tables again from the journal");
  return [o, import, find, series, priors, del] {
    if (import->parsed()) return runImport(*o);
    if (series->parsed()) return runSeries(*o);
    if (del->parsed()) return runDelete(*o);
    if (find->parsed()) {
      StudyQuery q = o->query;
      if (!o->dates.empty()) {
        size_t dash = o->dates.find('-');
        q.dateFrom = o->dates.substr(0, dash);
        q.dateTo = dash == std::string::npos ? q.dateFrom : o->dates.substr(dash + 1);
      }
      printStudies(openDb(o->db)->find(q), o->json, "no study matched");
      return 0;
    }
    if (priors->parsed()) {
      printStudies(openDb(o->db)->priors(o->study), o->json, "no earlier study of this patient");
      return 0;
    }
    return runVerify(*o);
  };
}

}  // namespace voxray::cli
#else
namespace voxray::cli {
Run addDbCommand(CLI::App& app) {
  app.add_subcommand("db", "Study database (not in this build)")->allow_extras();
  return []() -> int { throw inputError("this voxray-cli was built without DICOM"); };
}
}  // namespace voxray::cli
#endif
