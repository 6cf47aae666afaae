#include "input_options.h"

#include "progress.h"
#include "spec_options.h"
#include "voxray/engine/input_flags.h"
#include "voxray/io/error.h"
#include "voxray/io/phantom.h"
#ifdef VOXRAY_HAS_STUDYDB
#include "voxray/studydb/study_db.h"
#endif
#ifdef VOXRAY_HAS_DICOM  // the PACS client's library, which reads OME-Zarr URLs too
#include "voxray/io/zarr_url.h"
#endif

namespace voxray::cli {

void InputOptions::add(CLI::App& cmd) {
  cmd.add_option("input", input,
                 "DICOM file or folder, raw slice folder, printf pattern or raw file, "
                 "OME-Zarr folder or http(s):// URL, "
                 "db:SERIES_UID (a series of the study database) "
                 "(none: the embedded head phantom)");
  cmd.add_option("--db", db,
                 "study database folder for db:SERIES_UID, or with --series UID and no INPUT "
                 "(default: the user's, see voxray-cli db --help)");
  addSpecOptions(cmd, inputFlagSpecs(), flags);
  cmd.add_option("--phantom-size", phantomSize,
                 "no INPUT: voxels per axis of the head phantom (1024: a 2 GiB volume)")
      ->check(CLI::Range(2, 1024));
  // Not an input flag spec (the workstation's session has no field for it yet): CLI only.
  cmd.add_option("--level", level,
                 "OME-Zarr: the pyramid level to open, 0 (full resolution, the default) to the "
                 "coarsest")
      ->check(CLI::Range(0, 32));
}

LoadOptions InputOptions::loadOptions() const {
  LoadOptions o = loadOptionsFromFlags(flags);
  o.level = level;
  return o;
}

Volume InputOptions::load() const {
  LoadOptions o = loadOptions();
  std::string path = input;
  const bool fromDb = input.rfind("db:", 0) == 0 || (input.empty() && !db.empty());
  if (input.empty() && !fromDb) return makeHeadPhantom(phantomSize);
  if (fromDb) {
    const std::string uid = input.empty() ? o.series : input.substr(3);
    if (uid.empty())
      throw inputError(
          "--db needs the series to open: --series SERIES_UID, or db:SERIES_UID as "
          "INPUT (voxray-cli db series STUDY_UID lists them)");
#ifdef VOXRAY_HAS_STUDYDB
    StudyDb studies(db.empty() ? defaultStudyDbFolder() : db);
    SeriesInput series = studies.seriesInput(uid);
    path = series.folder;
    o.series = series.series;
#else
    throw inputError("this voxray-cli was built without DICOM: db:SERIES_UID cannot be opened");
#endif
  }
  o.progress = terminalProgress("loading");
#ifdef VOXRAY_HAS_DICOM
  return loadVolumeOrUrl(path, o);
#else
  return loadVolume(path, o);
#endif
}

}  // namespace voxray::cli
