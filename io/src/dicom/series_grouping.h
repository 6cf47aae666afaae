#pragma once
// Series discovery: images are grouped by series, then split where they cannot share one
// voxel grid (orientation, matrix, pixel spacing) or repeat positions (4D: one candidate
// per time point). Each candidate is classified as a volume or not, with the reason.
#include <string>
#include <vector>

#include "frame_header.h"

namespace voxray::dicom {

struct Candidate {
  std::vector<FrameHeader> frames;    // sorted along the slice normal when positions exist
  std::string selector;               // unique name: series number, UID, plus ":part"
  int part = 0;                       // 1.. when the series was split, else 0
  int timePoint = 0, timePoints = 1;  // 4D: which volume of how many (1-based)
  int group = 0;                      // the same for the time points of one 4D series
  // 4D whose positions have unequal repeats and whose images do not name their time point:
  // which image belongs to which time point is a guess.
  bool unevenTimePoints = false;
  bool isVolume = false;
  std::string notVolumeReason;
  std::vector<std::string> warnings;
  const FrameHeader& first() const { return frames.front(); }
};

// Candidates ordered for listing: volumes by size (largest first), then the others.
std::vector<Candidate> groupIntoCandidates(std::vector<FrameHeader> frames);

// The candidate SELECTOR names (selector, series number or UID); -1 when none.
int findCandidate(const std::vector<Candidate>& candidates, const std::string& selector);

}  // namespace voxray::dicom
