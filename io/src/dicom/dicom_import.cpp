// The DICOM import pipeline: find files, read headers in parallel, group into candidates,
// then decode the chosen one slice-parallel into int16, bring slices onto one value
// scale and, for tilted or uneven stacks, resample onto an orthogonal uniform grid.
#include "voxray/io/dicom_import.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <tuple>

#include "arrived_files.h"
#include "file_scan.h"
#include "not_dicom.h"
#include "pixel_decode.h"
#include "resample.h"
#include "series_grouping.h"
#include "slice_permute.h"
#include "stack_geometry.h"
#include "value_mapping.h"
#include "voxray/io/error.h"
#include "voxray/io/ome_zarr.h"
#include "voxray/io/parallel.h"
#include "voxray/io/raw_import.h"
#include "voxray/io/suv.h"

namespace voxray {
namespace {

using namespace dicom;

constexpr double kHeaderShare = 0.1;  // progress spent on reading headers

struct Scan {
  InputFiles input;
  std::vector<Candidate> candidates;
  std::vector<StackGeometry> geometry;  // per candidate
  int skipped = 0;
  std::vector<std::string> notes;
};

void report(const LoadOptions& o, double fraction, const std::string& message) {
  if (o.progress) o.progress(fraction, message);
}

void throwIfCancelled(const LoadOptions& o, const std::string& input) {
  if (o.cancel && *o.cancel) throw cancelledError(input + ": DICOM import cancelled");
}

// ARRIVED (may be null): files whose headers were read as they arrived; the others are read
// from disk.
Scan scan(const std::string& input, const LoadOptions& options, const ArrivedFiles* arrived) {
  Scan s;
  s.input = collectInputFiles(input);
  const auto& files = s.input.files;
  std::vector<std::vector<FrameHeader>> perFile(files.size());
  std::map<std::string, int> skippedWhy;
  std::map<std::string, int> notDicomKinds;  // files that are something Voxray can name
  std::mutex mutex;
  std::atomic<size_t> done{0};
  parallelFor(
      files.size(),
      [&](size_t i) {
        std::string why;
        if (const ArrivedFiles::File* early = arrived ? arrived->find(files[i]) : nullptr) {
          perFile[i] = early->frames;
          for (auto& f : perFile[i]) f.path = files[i];  // as the folder names it
        } else if (readFrameHeaders(files[i], perFile[i], why) != ScanResult::Image) {
          const std::string kind =
              why == "not a DICOM file" ? notDicomKind(files[i]) : std::string();
          std::lock_guard lock(mutex);
          ++(kind.empty() ? skippedWhy[why] : notDicomKinds[kind]);
        }
        size_t d = ++done;
        if (d % 16 == 0 || d == files.size())
          report(options, kHeaderShare * double(d) / double(files.size()), "Reading headers");
      },
      options.cancel);
  throwIfCancelled(options, input);
  std::vector<FrameHeader> frames;
  for (auto& list : perFile)
    for (auto& f : list) frames.push_back(std::move(f));
  for (auto& [kind, count] : notDicomKinds) {
    s.skipped += count;
    s.notes.push_back(notDicomNote(kind, count));
  }
  for (auto& [why, count] : skippedWhy) {
    s.skipped += count;
    s.notes.push_back(std::to_string(count) + " file(s) skipped: " + why);
  }
  s.notes.insert(s.notes.end(), s.input.notes.begin(), s.input.notes.end());
  if (frames.empty()) {
    // What the folder holds instead, each kind once (a few: TIFF, PNG, not DICOM ...).
    std::string detail;
    for (size_t i = 0; i < s.notes.size() && i < 3; ++i) detail += (i ? "; " : "") + s.notes[i];
    if (!detail.empty()) detail = " (" + detail + ")";
    throw inputError(input + ": no DICOM image found in " + std::to_string(files.size()) +
                     " file(s)" + detail + ". Choose a DICOM file, folder or DICOMDIR.");
  }
  s.candidates = groupIntoCandidates(std::move(frames));
  for (auto& c : s.candidates) {
    StackGeometry g;
    try {
      g = analyseStack(c.frames);
    } catch (const Error& e) {
      c.isVolume = false;
      c.notVolumeReason = e.what();
      g.source.dims = g.target.dims = {c.first().columns, c.first().rows, int(c.frames.size())};
    }
    s.geometry.push_back(std::move(g));
  }
  return s;
}

SeriesInfo describe(const Candidate& c, const StackGeometry& g) {
  const FrameHeader& f = c.first();
  SeriesInfo info;
  info.selector = c.selector;
  info.uid = f.seriesUid;
  info.number = f.seriesNumber;
  info.part = c.part;
  info.description = f.description;
  info.modality = f.modality;
  info.transferSyntax = transferSyntaxName(f.transferSyntaxUid);
  info.dims = g.target.dims;
  info.spacingMm = g.target.spacing;
  info.originMm = g.target.origin;
  info.direction = g.target.axes;
  info.sliceCount = int(c.frames.size());
  std::map<std::string, int> files;
  for (auto& fr : c.frames) ++files[fr.path];
  info.fileCount = int(files.size());
  info.isVolume = c.isVolume;
  info.notVolumeReason = c.notVolumeReason;
  info.warnings = c.warnings;
  info.warnings.insert(info.warnings.end(), g.warnings.begin(), g.warnings.end());
  info.patientName = f.patientName;
  info.patientId = f.patientId;
  info.patientBirthDate = f.patientBirthDate;
  return info;
}

int defaultChoice(const Scan& s) {
  for (size_t i = 0; i < s.candidates.size(); ++i)
    if (s.candidates[i].isVolume) return int(i);
  return -1;
}

// At most a screenful: a damaged multi-frame file can split into thousands of candidates.
std::string candidateList(const Scan& s) {
  constexpr size_t kShown = 12;
  std::string out;
  for (size_t i = 0; i < s.candidates.size(); ++i) {
    if (i == kShown) {
      out += "\n  ... and " + std::to_string(s.candidates.size() - kShown) + " more";
      break;
    }
    const Candidate& c = s.candidates[i];
    out += "\n  " + c.selector + ": " + std::to_string(c.frames.size()) + " image(s) " +
           c.first().modality;
    if (!c.first().description.empty()) out += " \"" + c.first().description + "\"";
    if (!c.isVolume) out += " - " + c.notVolumeReason;
  }
  return out;
}

int chooseCandidate(const Scan& s, const std::string& input, const LoadOptions& options,
                    std::vector<std::string>& warnings) {
  if (!options.series.empty()) {
    int i = findCandidate(s.candidates, options.series);
    if (i < 0)
      throw inputError(input + ": no series \"" + options.series +
                       "\". Choose one of:" + candidateList(s));
    const Candidate& c = s.candidates[size_t(i)];
    if (!c.isVolume)
      warnings.push_back("series " + c.selector + " is not a volume (" + c.notVolumeReason +
                         "); loaded as requested");
    return i;
  }
  int i = defaultChoice(s);
  if (i >= 0) return i;
  // A single image file is opened as what it is: the user asked for exactly this file.
  if (s.input.singleFile && s.candidates.size() == 1) {
    warnings.push_back("not a volume (" + s.candidates[0].notVolumeReason +
                       "); loaded as a single file");
    return 0;
  }
  throw inputError(input + ": no series here is a 3D volume:" + candidateList(s) +
                   "\nChoose one with --series to open it anyway.");
}

// Decodes the slices of C not yet DONE into VOXELS (slice k at k * slice size) and their
// SCALES.
void decodeSlices(const Candidate& c, const LoadOptions& options, const std::vector<bool>& done0,
                  VoxelVector& voxels, std::vector<SliceScale>& scales) {
  const FrameHeader& f0 = c.first();
  const size_t sliceSize = size_t(f0.columns) * size_t(f0.rows);
  std::map<std::string, std::vector<size_t>> byFile;  // frames in file order
  for (size_t k = 0; k < c.frames.size(); ++k)
    if (!done0[k]) byFile[c.frames[k].path].push_back(k);
  std::vector<const std::vector<size_t>*> tasks;
  for (auto& [path, list] : byFile) {
    std::sort(list.begin(), list.end(), [&](size_t a, size_t b) {
      return c.frames[a].imageIndex() < c.frames[b].imageIndex();
    });
    tasks.push_back(&list);
  }
  std::atomic<size_t> done{size_t(std::count(done0.begin(), done0.end(), true))};
  const double air = airValue(f0.modality);
  const size_t total = c.frames.size();
  parallelFor(
      tasks.size(),
      [&](size_t t) {
        const auto& slices = *tasks[t];
        // Uncompressed 16-bit frames are read from the file into their slices; the first
        // one that cannot be sends the rest of the file the general way, which reports
        // whatever is wrong with it as before.
        auto first = slices.begin();
        {
          NativeFrames native(c.frames[*first].path);
          for (; first != slices.end(); ++first) {
            if (options.cancel && *options.cancel) return;
            const FrameHeader& h = c.frames[*first];
            auto* words = reinterpret_cast<uint16_t*>(voxels.data() + *first * sliceSize);
            if (size_t(h.columns) * size_t(h.rows) != sliceSize || !native.read(h, words)) break;
            scales[*first] = storeWords(words, sliceSize, h, air);
            size_t d = ++done;
            report(options, kHeaderShare + (0.9 - kHeaderShare) * double(d) / double(total),
                   "Decoding slice " + std::to_string(d) + " of " + std::to_string(total));
          }
        }
        if (first == slices.end()) return;
        PixelFile file(c.frames[*first].path);
        std::vector<int32_t> values;
        for (size_t k : std::vector<size_t>(first, slices.end())) {
          if (options.cancel && *options.cancel) return;
          const FrameHeader& h = c.frames[k];
          file.frameValues(h, values);
          if (values.size() != sliceSize)
            throw inputError(h.path + ": frame " + std::to_string(h.frame + 1) +
                             " does not have the " + std::to_string(f0.columns) + "x" +
                             std::to_string(f0.rows) + " pixels of the series");
          scales[k] = storeSlice(values, h, air, voxels.data() + k * sliceSize);
          size_t d = ++done;
          report(options, kHeaderShare + (0.9 - kHeaderShare) * double(d) / double(total),
                 "Decoding slice " + std::to_string(d) + " of " + std::to_string(total));
        }
      },
      options.cancel);
}

// Page tables for the BYTES at P, made on every core: the volume's first touch (50,000
// page faults for a 512x512x400 CT) was over a quarter of the import's CPU time, all on one
// core inside the vector's zero fill. Kernels before Linux 5.14 ignore the request.
void prefault(void* p, size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  constexpr uintptr_t kPage = 4096;
  constexpr size_t kChunk = size_t(8) << 20;
  const uintptr_t from = (reinterpret_cast<uintptr_t>(p) + kPage - 1) & ~(kPage - 1);
  const uintptr_t to = (reinterpret_cast<uintptr_t>(p) + bytes) & ~(kPage - 1);
  if (to <= from) return;
  parallelFor((to - from + kChunk - 1) / kChunk, [&](size_t i) {
    const uintptr_t a = from + i * kChunk, b = std::min<uintptr_t>(to, a + kChunk);
    madvise(reinterpret_cast<void*>(a), b - a, MADV_POPULATE_WRITE);
  });
#else
  (void)p;
  (void)bytes;
#endif
}

// The slices of C in VOXELS (VOXEL_COUNT of them) and their scales. Slices decoded as their
// files arrived are used where they fit this candidate (the same slice size and padding
// value): when they are exactly its slices, the arrival buffer is reordered in place and
// becomes the volume; the rest is decoded from disk.
std::vector<SliceScale> assembleSlices(const Candidate& c, const LoadOptions& options,
                                       ArrivedFiles* arrived, size_t voxelCount,
                                       VoxelVector& voxels) {
  const FrameHeader& f0 = c.first();
  const size_t sliceSize = size_t(f0.columns) * size_t(f0.rows);
  const double air = airValue(f0.modality);
  constexpr size_t kNone = size_t(-1);
  std::vector<size_t> source(c.frames.size(), kNone);
  size_t found = 0;
  if (arrived && arrived->sliceSize() == sliceSize) {
    for (size_t k = 0; k < c.frames.size(); ++k) {
      const ArrivedFiles::File* file = arrived->find(c.frames[k].path);
      const size_t image = size_t(c.frames[k].imageIndex());  // slots are kept per image
      if (!file || image >= file->slots.size()) continue;
      const size_t slot = file->slots[image];
      if (arrived->slots()[slot].air != air) continue;
      source[k] = slot;
      ++found;
    }
  }
  std::vector<SliceScale> scales(c.frames.size());
  for (size_t k = 0; k < c.frames.size(); ++k)
    if (source[k] != kNone) scales[k] = arrived->slots()[source[k]].scale;
  if (found > 0 && found == c.frames.size() && arrived->slots().size() == found) {
    permuteSlices(arrived->voxels(), sliceSize, source);
    voxels = arrived->release();
    report(options, 0.9, "Decoded " + std::to_string(found) + " slices as they arrived");
    return scales;
  }
  voxels.reserve(voxelCount);
  prefault(voxels.data(), voxelCount * sizeof(int16_t));
  voxels.resize(voxelCount);
  std::vector<bool> done(c.frames.size(), false);
  for (size_t k = 0; k < c.frames.size(); ++k) {
    if (source[k] == kNone) continue;
    std::copy_n(arrived->voxels().data() + source[k] * sliceSize, sliceSize,
                voxels.data() + k * sliceSize);
    done[k] = true;
  }
  if (found > 0)
    report(options, kHeaderShare,
           "Took " + std::to_string(found) + " slices decoded as they arrived");
  decodeSlices(c, options, done, voxels, scales);
  return scales;
}

// A damaged header can claim a huge image; no real file compresses 10000:1, so refuse
// before allocating what the files cannot hold.
void checkPlausibleSize(const Candidate& c, size_t bytes) {
  std::set<std::string> paths;
  for (auto& f : c.frames) paths.insert(f.path);
  uintmax_t fileBytes = 0;
  for (auto& p : paths) {
    std::error_code ec;
    uintmax_t size = std::filesystem::file_size(p, ec);
    if (!ec) fileBytes += size;
  }
  if (bytes > (uintmax_t(64) << 20) && bytes / 10000 > fileBytes)
    throw inputError(c.first().path + ": the header claims " + std::to_string(bytes >> 20) +
                     " MB of pixels but the files hold only " + std::to_string(fileBytes >> 10) +
                     " KB; the data is damaged");
}

StudyIdentity studyIdentity(const FrameHeader& f) {
  StudyIdentity id;
  id.patientName = f.patientName;
  id.patientId = f.patientId;
  id.patientBirthDate = f.patientBirthDate;
  id.studyInstanceUid = f.studyUid;
  id.studyDate = f.studyDate;
  id.studyTime = f.studyTime;
  id.studyDescription = f.studyDescription;
  id.accessionNumber = f.accession;
  id.studyId = f.studyId;
  id.seriesInstanceUid = f.seriesUid;
  id.seriesDescription = f.description;
  id.frameOfReferenceUid = f.frameOfReferenceUid;
  id.seriesNumber = f.seriesNumber;
  return id;
}

// The resampled grid holds every acquired pixel; what lies beyond the slices is padding.
std::string paddingNote(size_t padded, size_t total, double air, const std::string& modality) {
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%.1f %% of the resampled grid lies outside the acquired slices and is filled "
                "with %s (%g%s)",
                100.0 * double(padded) / double(total), modality == "CT" ? "air" : "zero", air,
                modality == "CT" ? " HU" : "");
  return buf;
}

std::string sampleTypeName(const FrameHeader& f) {
  return std::string(f.pixelRepresentation ? "i" : "u") + std::to_string(f.bitsStored);
}

}  // namespace

DicomListing listDicomSeries(const std::string& input, const LoadOptions& options) {
  // Not a scan of thousands of chunk files for a DICOM header: say what it is.
  if (isOmeZarr(input))
    throw inputError(input + ": is an OME-Zarr folder, not DICOM; open it as it is (voxray-cli " +
                     "info or render FOLDER, or drop it on the workstation's window)");
  Scan s = scan(input, options, nullptr);
  DicomListing listing;
  listing.filesScanned = int(s.input.files.size());
  listing.filesSkipped = s.skipped;
  listing.notes = s.notes;
  int chosen = defaultChoice(s);
  for (size_t i = 0; i < s.candidates.size(); ++i) {
    listing.series.push_back(describe(s.candidates[i], s.geometry[i]));
    listing.series.back().chosenByDefault = int(i) == chosen;
  }
  return listing;
}

namespace {

// The time point options.timePoint of the series of candidate INDEX (itself for a 3D series).
int chooseTimePoint(const Scan& s, int index, const std::string& input,
                    const LoadOptions& options) {
  const Candidate& c = s.candidates[size_t(index)];
  if (!options.timePoint) return index;
  const int t = *options.timePoint;
  if (t < 0 || t >= c.timePoints)
    throw inputError(input + ": --time " + std::to_string(t) + " is out of range: series " +
                     std::to_string(c.first().seriesNumber) + " has " +
                     std::to_string(c.timePoints) + " time point(s)" +
                     (c.timePoints > 1 ? ", 0 to " + std::to_string(c.timePoints - 1) : ""));
  for (size_t i = 0; i < s.candidates.size(); ++i)
    if (s.candidates[i].group == c.group && s.candidates[i].timePoint == t + 1) return int(i);
  return index;
}

// PET: Bq/mL and, when the attributes allow it, the SUVbw scale; else why not, as a warning.
void describePet(const Candidate& c, Volume& v) {
  const FrameHeader& f0 = c.first();
  if (!f0.pet) return;
  PetSuvAttributes a = *f0.pet;
  // The earliest image (DA and TM text compare in time order when both are given).
  for (const auto& f : c.frames) {
    if (f.acquisitionTime.empty()) continue;
    if (a.acquisitionTime.empty() || std::tie(f.acquisitionDate, f.acquisitionTime) <
                                         std::tie(a.acquisitionDate, a.acquisitionTime)) {
      a.acquisitionDate = f.acquisitionDate;
      a.acquisitionTime = f.acquisitionTime;
    }
  }
  if (a.units == "BQML")
    v.unit = "Bq/mL";
  else if (!a.units.empty())
    v.unit = a.units;
  try {
    v.suv = suvbwScale(a);
  } catch (const Error& e) {
    v.warnings.push_back(e.what());
  }
}

Volume decodeCandidate(const Scan& s, int index, const std::string& input,
                       const LoadOptions& options, ArrivedFiles* arrived,
                       std::vector<std::string> warnings,
                       std::optional<ValueRange>* range = nullptr);

// RANGE (may be null): the volume's stored range where the slices' own ranges give it.
Volume importWith(const std::string& input, const LoadOptions& options, ArrivedFiles* arrived,
                  std::optional<ValueRange>* range = nullptr) {
  if (arrived) {
    arrived->drain(options.cancel);
    throwIfCancelled(options, input);
  }
  Scan s = scan(input, options, arrived);
  std::vector<std::string> warnings;
  const int index =
      chooseTimePoint(s, chooseCandidate(s, input, options, warnings), input, options);
  return decodeCandidate(s, index, input, options, arrived, std::move(warnings), range);
}

Volume decodeCandidate(const Scan& s, int index, const std::string& input,
                       const LoadOptions& options, ArrivedFiles* arrived,
                       std::vector<std::string> warnings, std::optional<ValueRange>* range) {
  const Candidate& c = s.candidates[size_t(index)];
  const FrameHeader& f0 = c.first();
  if (std::string why = unsupportedReason(f0); !why.empty()) throw inputError(f0.path + ": " + why);
  StackGeometry g = analyseStack(c.frames);  // throws when slices coincide
  const Grid& src = g.source;
  const size_t voxelCount = size_t(src.dims.x) * size_t(src.dims.y) * size_t(src.dims.z);
  const size_t targetCount = size_t(g.target.dims.x) * g.target.dims.y * size_t(g.target.dims.z);
  if (voxelCount > kMaxVoxels || targetCount > kMaxVoxels)
    throw inputError(input + ": series " + c.selector + " is too large to load (" +
                     std::to_string(std::max(voxelCount, targetCount)) + " voxels)");

  checkPlausibleSize(c, std::max(voxelCount, targetCount) * sizeof(int16_t));

  Volume v;
  std::vector<SliceScale> scales = assembleSlices(c, options, arrived, voxelCount, v.voxels);
  throwIfCancelled(options, input);
  CommonScale common = chooseCommonScale(scales);
  const size_t sliceSize = size_t(src.dims.x) * size_t(src.dims.y);
  if (common.remap) {
    parallelFor(scales.size(), [&](size_t k) {
      remapSlice(v.voxels.data() + k * sliceSize, sliceSize, scales[k], common);
    });
    warnings.push_back(common.warning);
  }
  if (range && !common.remap && !g.needsResampling && !scales.empty()) {
    // The voxels are the slices as stored (storeWords/storeSlice measured each one).
    ValueRange r{scales[0].min, scales[0].max};
    for (const SliceScale& sc : scales) {
      r.min = std::min(r.min, sc.min);
      r.max = std::max(r.max, sc.max);
    }
    *range = r;
  }
  if (g.needsResampling) {
    report(options, 0.92, "Resampling to a uniform grid");
    std::vector<glm::dvec3> origins;
    for (auto& f : c.frames) origins.push_back(f.position);
    const double air = airValue(f0.modality);
    auto outside = int16_t(std::clamp(std::lround((air - common.intercept) / common.slope),
                                      long(INT16_MIN), long(INT16_MAX)));
    Resampled resampled = resampleStack(v.voxels, origins, g, outside, options.cancel);
    throwIfCancelled(options, input);
    v.voxels = std::move(resampled.voxels);
    if (resampled.padded > 0)
      g.warnings.push_back(paddingNote(resampled.padded, v.voxels.size(), air, f0.modality));
  }
  v.dims = g.target.dims;
  v.spacingMm = g.target.spacing;
  v.originMm = g.target.origin;
  v.direction = g.target.axes;
  v.slope = common.slope;
  v.intercept = common.intercept;
  v.unit = f0.modality == "CT" ? "HU" : f0.modality + " signal (scanner units)";
  v.modality = f0.modality;
  v.window = f0.window;  // the first slice's: what a viewer shows when the series opens
  v.study = studyIdentity(f0);
  v.study.sopClassUid = f0.sopClassUid;
  // Slice k is frame k of the sorted stack only when nothing was resampled (a mosaic's
  // slices share one SOP instance).
  if (!g.needsResampling && !f0.isEnhanced() && !f0.mosaic && int(c.frames.size()) == v.dims.z) {
    for (auto& f : c.frames) v.study.sliceSopInstanceUids.push_back(f.sopInstanceUid);
    if (std::any_of(c.frames.begin(), c.frames.end(),
                    [](const FrameHeader& f) { return f.sopInstanceUid.empty(); }))
      v.study.sliceSopInstanceUids.clear();
  }
  v.sourceType = sampleTypeName(f0);
  v.timePoint = c.timePoint - 1;
  v.timePoints = c.timePoints;
  v.warnings = c.warnings;
  v.warnings.insert(v.warnings.end(), g.warnings.begin(), g.warnings.end());
  v.warnings.insert(v.warnings.end(), warnings.begin(), warnings.end());
  if (isLuminanceRgb(f0))
    v.warnings.push_back("colour (RGB) images: shown as their luminance, greyscale 0-255");
  for (auto& note : s.notes) v.warnings.push_back(note);
  describePet(c, v);
  report(options, 1.0, "Loaded");
  return v;
}

}  // namespace

Volume importDicom(const std::string& input, const LoadOptions& options) {
  return importWith(input, options, nullptr);
}

std::vector<Volume> importDicomTimePoints(const std::string& input, const LoadOptions& options) {
  Scan s = scan(input, options, nullptr);
  std::vector<std::string> warnings;
  const int chosen = chooseCandidate(s, input, options, warnings);
  if (s.candidates[size_t(chosen)].unevenTimePoints)
    throw inputError(input + ": series " +
                     std::to_string(s.candidates[size_t(chosen)].first().seriesNumber) +
                     " has fewer images at some slice positions than at others and its images "
                     "do not say their time point (Temporal Position Identifier, Trigger Time): "
                     "it cannot be split into time points reliably; open them one by one with "
                     "--time, or check the series is complete");
  std::vector<int> indices(size_t(s.candidates[size_t(chosen)].timePoints), chosen);
  for (size_t i = 0; i < s.candidates.size(); ++i)
    if (s.candidates[i].group == s.candidates[size_t(chosen)].group)
      indices[size_t(s.candidates[i].timePoint - 1)] = int(i);
  std::vector<Volume> out;
  for (int i : indices) {
    out.push_back(decodeCandidate(s, i, input, options, nullptr, warnings));
    const Volume& v = out.back();
    if (v.dims != out.front().dims || v.spacingMm != out.front().spacingMm ||
        v.originMm != out.front().originMm)
      throw inputError(input + ": time point " + std::to_string(v.timePoint) + " of series " +
                       s.candidates[size_t(i)].selector +
                       " has another geometry than time point 0; open them one by one with "
                       "--time");
  }
  return out;
}

DicomImport::DicomImport(LoadOptions options)
    : options_(std::move(options)), arrived_(std::make_unique<ArrivedFiles>()) {}

DicomImport::~DicomImport() = default;

void DicomImport::add(const std::string& path, std::string bytes) {
  arrived_->add(path, std::make_shared<const std::string>(std::move(bytes)));
}

void DicomImport::add(const std::string& path, std::shared_ptr<const std::string> bytes) {
  arrived_->add(path, std::move(bytes));
}

std::optional<ArrivedInstance> DicomImport::instance(const std::string& path) {
  arrived_->drain(options_.cancel);
  if (options_.cancel && *options_.cancel) return std::nullopt;
  const dicom::ArrivedFiles::File* file = arrived_->find(path);
  if (!file || file->frames.empty()) return std::nullopt;
  const dicom::FrameHeader& h = file->frames.front();
  return ArrivedInstance{h.sopClassUid, h.seriesUid, h.sopInstanceUid};
}

Volume DicomImport::finish(const std::string& input) {
  range_.reset();
  return importWith(input, options_, arrived_.get(), &range_);
}

}  // namespace voxray
