#include "series_grouping.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

#include "pixel_decode.h"

namespace voxray::dicom {
namespace {

constexpr double kDirectionTolerance = 1e-3;  // cosines; scanners print 6-8 digits
constexpr double kPositionTolerance = 0.01;   // mm: two images at one slice position
constexpr int kMinVolumeSlices = 3;

bool near(const glm::dvec3& a, const glm::dvec3& b, double tol) {
  return std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol;
}

bool sameGrid(const FrameHeader& a, const FrameHeader& b) {
  return a.rows == b.rows && a.columns == b.columns && a.samplesPerPixel == b.samplesPerPixel &&
         a.bitsAllocated == b.bitsAllocated && a.hasOrientation == b.hasOrientation &&
         near(a.rowDir, b.rowDir, kDirectionTolerance) &&
         near(a.colDir, b.colDir, kDirectionTolerance) &&
         std::abs(a.pixelSpacing.x - b.pixelSpacing.x) <= 1e-4 * a.pixelSpacing.x &&
         std::abs(a.pixelSpacing.y - b.pixelSpacing.y) <= 1e-4 * a.pixelSpacing.y;
}

bool upper(const std::string& s, const char* word) {
  std::string u = s;
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return std::toupper(c); });
  return u.find(word) != std::string::npos;
}

auto acquisitionOrder(const FrameHeader& f) {
  return std::make_tuple(f.temporalIndex, f.triggerTime, f.acquisitionNumber, f.instanceNumber,
                         f.path, f.frame);
}

// Splits one grid group into time points when positions repeat.
// UNEVEN: some positions have fewer images than others; UNNAMED: the images do not say which
// time point they are.
std::vector<std::vector<FrameHeader>> splitTimePoints(std::vector<FrameHeader> g, bool& uneven,
                                                      bool& unnamed) {
  uneven = false;
  unnamed = true;
  if (!g.front().hasPosition) {
    std::sort(g.begin(), g.end(),
              [](auto& a, auto& b) { return acquisitionOrder(a) < acquisitionOrder(b); });
    return {std::move(g)};
  }
  const glm::dvec3 n = g.front().normal();
  std::sort(g.begin(), g.end(), [&](const FrameHeader& a, const FrameHeader& b) {
    double da = glm::dot(a.position, n), db = glm::dot(b.position, n);
    if (std::abs(da - db) > kPositionTolerance) return da < db;
    return acquisitionOrder(a) < acquisitionOrder(b);
  });
  // Clusters of images at one position, in acquisition order inside each cluster.
  std::vector<std::vector<FrameHeader>> positions;
  for (auto& f : g) {
    if (positions.empty() ||
        !near(positions.back().front().position, f.position, kPositionTolerance))
      positions.emplace_back();
    positions.back().push_back(std::move(f));
  }
  size_t repeats = 1;
  for (auto& p : positions) repeats = std::max(repeats, p.size());
  // When the images name their time point (Temporal Position Identifier or Index, Trigger
  // Time), the phases are those names: an image missing from one phase leaves a gap in that
  // phase only. Without names the k-th image at each position is time point k.
  std::set<std::pair<int, double>> phases;
  for (auto& p : positions)
    for (auto& f : p) phases.insert({f.temporalIndex, f.triggerTime});
  bool named = phases.size() == repeats && repeats > 1;
  for (auto& p : positions) {
    std::set<std::pair<int, double>> here;
    for (auto& f : p) here.insert({f.temporalIndex, f.triggerTime});
    named = named && here.size() == p.size();
  }
  std::vector<std::vector<FrameHeader>> volumes(repeats);
  for (auto& p : positions) {
    uneven |= p.size() != repeats;
    for (size_t t = 0; t < p.size(); ++t) {
      const size_t phase =
          named ? size_t(std::distance(phases.begin(),
                                       phases.find({p[t].temporalIndex, p[t].triggerTime})))
                : t;
      volumes[phase].push_back(std::move(p[t]));
    }
  }
  unnamed = !named;
  return volumes;
}

void classify(Candidate& c) {
  const FrameHeader& f = c.first();
  const int n = int(c.frames.size());
  if (std::string why = unsupportedReason(f); !why.empty()) {
    c.notVolumeReason = "the image " + why;
  } else if (f.sopClassUid.rfind("1.2.840.10008.5.1.4.1.1.7", 0) == 0) {
    c.notVolumeReason = "secondary capture (screenshots or report pages)";
  } else if (upper(f.imageType, "LOCALIZER") || upper(f.imageType, "SCOUT") ||
             upper(f.imageType, "SURVIEW")) {
    c.notVolumeReason = "a localizer (scout) image";
  } else if (n < kMinVolumeSlices) {
    c.notVolumeReason = n == 1 ? "a single image" : "only " + std::to_string(n) + " images";
  } else if (!f.hasPosition || !f.hasOrientation) {
    c.notVolumeReason = "the images carry no position or orientation";
  } else {
    c.isVolume = true;
  }
}

std::string numberName(int number) { return std::to_string(number); }

}  // namespace

std::vector<Candidate> groupIntoCandidates(std::vector<FrameHeader> frames) {
  // Series: same UID and same number (one UID re-used for differently numbered series
  // happens when files were exported one by one).
  // Multi-frame files without positions cannot be ordered against each other: each file
  // stays its own series (copies of one object in several transfer syntaxes, say).
  std::map<std::tuple<std::string, int, std::string>, std::vector<FrameHeader>> series;
  for (auto& f : frames) {
    std::string file = (!f.hasPosition && f.fileFrames > 1) ? f.path : std::string();
    series[{f.seriesUid, f.seriesNumber, file}].push_back(std::move(f));
  }

  std::map<int, int> numberUse;
  std::map<std::string, int> uidUse;
  for (auto& [key, list] : series) {
    ++numberUse[std::get<1>(key)];
    ++uidUse[std::get<0>(key)];
  }

  std::vector<Candidate> out;
  int groups = 0;
  for (auto& [key, list] : series) {
    std::vector<std::vector<FrameHeader>> grids;
    for (auto& f : list) {
      auto it =
          std::find_if(grids.begin(), grids.end(), [&](auto& g) { return sameGrid(g.front(), f); });
      if (it == grids.end())
        grids.push_back({std::move(f)});
      else
        it->push_back(std::move(f));
    }
    const auto& [uid, number, file] = key;
    std::string base = numberUse[number] == 1 ? numberName(number)
                       : uidUse[uid] == 1     ? uid
                                              : uid + "/" + numberName(number);
    if (!file.empty()) base += "@" + std::filesystem::path(file).filename().string();
    std::vector<Candidate> parts;
    for (auto& g : grids) {
      bool uneven = false, unnamed = true;
      auto volumes = splitTimePoints(std::move(g), uneven, unnamed);
      ++groups;
      for (size_t t = 0; t < volumes.size(); ++t) {
        Candidate c;
        c.group = groups;
        c.frames = std::move(volumes[t]);
        c.timePoint = int(t) + 1;
        c.timePoints = int(volumes.size());
        if (c.timePoints > 1) {
          c.warnings.push_back(
              "the series holds " + std::to_string(c.timePoints) +
              " images at each slice position (4D: time points, phases or diffusion "
              "directions); this is time point " +
              std::to_string(c.timePoint - 1) + " of 0-" + std::to_string(c.timePoints - 1) +
              " (--time chooses another), never stacked with the others");
          if (uneven) {
            c.warnings.push_back(unnamed ? "some slice positions have fewer repeats than others; "
                                           "the images do not say their time point, so the later "
                                           "volumes miss slices or mix time points"
                                         : "some slice positions have fewer repeats than others; "
                                           "those time points miss slices");
            c.unevenTimePoints = unnamed;
          }
        }
        parts.push_back(std::move(c));
      }
    }
    if (grids.size() > 1)
      for (auto& c : parts)
        c.warnings.push_back("the series mixes " + std::to_string(grids.size()) +
                             " image geometries (orientation, matrix or pixel spacing); "
                             "each is listed separately");
    for (size_t p = 0; p < parts.size(); ++p) {
      parts[p].part = parts.size() > 1 ? int(p) + 1 : 0;
      parts[p].selector = parts.size() > 1 ? base + ":" + std::to_string(p + 1) : base;
      classify(parts[p]);
      out.push_back(std::move(parts[p]));
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
    if (a.isVolume != b.isVolume) return a.isVolume;
    auto voxels = [](const Candidate& c) {
      return double(c.first().rows) * c.first().columns * double(c.frames.size());
    };
    if (a.isVolume && voxels(a) != voxels(b)) return voxels(a) > voxels(b);
    return std::make_tuple(a.first().seriesNumber, a.part) <
           std::make_tuple(b.first().seriesNumber, b.part);
  });
  return out;
}

int findCandidate(const std::vector<Candidate>& candidates, const std::string& selector) {
  for (size_t i = 0; i < candidates.size(); ++i)
    if (candidates[i].selector == selector) return int(i);
  // A bare number or UID of a split series means its first part (as listed).
  for (size_t i = 0; i < candidates.size(); ++i) {
    const FrameHeader& f = candidates[i].first();
    if (f.seriesUid == selector || numberName(f.seriesNumber) == selector) return int(i);
  }
  return -1;
}

}  // namespace voxray::dicom
