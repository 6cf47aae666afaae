#pragma once
// DICOM import: a folder (searched recursively), a single file or a DICOMDIR becomes one
// Volume in physical units (HU for CT). Series are discovered by SeriesInstanceUID and
// split where geometry differs; the largest true volume is chosen unless the caller
// selects another. Only std and GLM types here: DCMTK and OpenJPEG stay private.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/io/load.h"
#include "voxray/io/volume.h"

namespace voxray {
namespace dicom {
class ArrivedFiles;
}

// One candidate volume found in the input, described from headers only (no pixels read).
struct SeriesInfo {
  std::string selector;        // pass as LoadOptions::series to load exactly this candidate
  std::string uid;             // SeriesInstanceUID (several candidates may share one)
  int number = 0;              // SeriesNumber
  int part = 0;                // 1.. when one series was split into several candidates, else 0
  std::string description;     // SeriesDescription
  std::string modality;        // CT, MR, ...
  std::string transferSyntax;  // name of the first file's transfer syntax
  glm::ivec3 dims{0};          // columns, rows, slices as they would be loaded
  glm::dvec3 spacingMm{0.0};   // column, row and slice spacing (slice: from positions)
  glm::dvec3 originMm{0.0};    // LPS centre of the first voxel, as loaded
  glm::dmat3 direction{1.0};   // columns: LPS unit vectors of i, j, k
  int sliceCount = 0;          // images (frames) in this candidate
  int fileCount = 0;
  bool isVolume = false;              // a 3D stack that can be chosen by default
  bool chosenByDefault = false;       // the candidate loadVolume opens when no series is given
  std::string notVolumeReason;        // why isVolume is false (scout, single slice, ...)
  std::vector<std::string> warnings;  // tilt, uneven gaps, missing slices, 4D, ...
  // For display in the UI only: never log these or put them in messages or exports.
  std::string patientName;
  std::string patientId;
  std::string patientBirthDate;
};

struct DicomListing {
  std::vector<SeriesInfo> series;  // volumes first (largest first), then the others
  int filesScanned = 0;
  int filesSkipped = 0;  // not DICOM, unreadable, or DICOM without an image (DICOMDIR, SR)
  std::vector<std::string> notes;  // what was skipped and why, without patient data
};

// Reads headers only. Throws Error (Input) when INPUT does not exist or holds no image.
DicomListing listDicomSeries(const std::string& input, const LoadOptions& options = {});

// Loads the candidate named by options.series (selector, series number or UID), else the
// default choice. Slices are decoded in parallel; options.progress is called from worker
// threads and options.cancel abandons the load (throws Error). Throws Error (Input) with
// a message naming the file and the reason when the data cannot be one volume.
Volume importDicom(const std::string& input, const LoadOptions& options = {});

// Every time point of the series importDicom would open (options.timePoint ignored), in time
// order; one volume for a 3D series. Throws Error (Input) when time points differ in geometry.
std::vector<Volume> importDicomTimePoints(const std::string& input,
                                          const LoadOptions& options = {});

// importDicom for files that arrive while the import runs (a PACS retrieval into a folder):
// each file handed to add() has its headers read and its pixels decoded on a worker at once,
// and finish() imports INPUT as importDicom(INPUT, OPTIONS) does, using that work for the
// files at the same paths and reading the others from disk. The volume and the errors are
// importDicom's: what the worker could not do is done again from the file on disk.
// Who a file handed to DicomImport::add is, as its import read it.
struct ArrivedInstance {
  std::string sopClassUid, seriesInstanceUid, sopInstanceUid;
};

class DicomImport {
 public:
  explicit DicomImport(LoadOptions options = {});
  ~DicomImport();  // stops the worker, drops what it did
  DicomImport(const DicomImport&) = delete;
  DicomImport& operator=(const DicomImport&) = delete;

  // BYTES: the whole content of the file at PATH (there, or written there before finish()).
  // May be called from any one thread at a time.
  void add(const std::string& path, std::string bytes);
  // The same with the bytes shared, not copied (the PACS cache writes them to the file).
  void add(const std::string& path, std::shared_ptr<const std::string> bytes);
  // The file added at PATH once the worker has read it, when it is an image it decoded
  // completely; else none (or cancelled). Waits for the worker: the PACS cache takes a
  // series' identities from here instead of parsing each file a second time.
  std::optional<ArrivedInstance> instance(const std::string& path);
  // Waits for the worker (options.cancel stops the wait and throws Cancelled), then imports.
  Volume finish(const std::string& input);
  // The stored range (storedRange) of the volume finish() returned, when the import knows it
  // from its slices without another pass over the voxels (no rescale, no resampling); else
  // none. A pass over a 400-slice CT was 0.03 s of pacs get's critical path.
  std::optional<ValueRange> storedRange() const { return range_; }

 private:
  LoadOptions options_;
  std::unique_ptr<dicom::ArrivedFiles> arrived_;
  std::optional<ValueRange> range_;
};

}  // namespace voxray
