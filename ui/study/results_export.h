#pragma once
// Results out of the workstation (issue 37): the open study's measurements as the report
// writers' structs, the slices marked as key images, and where results may be written. The
// writing itself is io/report's (the functions voxray-cli export-sr, key-images and
// anonymise call), so the workstation and the CLI write the same files.
#include <string>
#include <vector>

#include "measurement_model.h"
#include "no_qt.h"
#include "notifier.h"
#include "voxray/io/measurement_report.h"
#include "voxray/io/segmentation.h"

namespace voxray {

// M's measurements of V with the engine's values, labelled as voxray-cli export-sr labels
// them ("line 1", "angle 1", "ellipse 1", "rect 1", numbered per kind in list order).
// A distance picked in the 3D view is in3d (SCOORD3D in the SR).
std::vector<ReportMeasurement> reportMeasurements(const Volume& v, const MeasurementModel& m);
// The segments of S (on V's grid) as report groups labelled "segment LABEL NAME": their
// statistics, volume and SUVpeak (V's SUV, else the fused OVERLAY's; segment_peak.h), their
// centroid (voxels) and their number in a DICOM SEG written from S (its order in S).
std::vector<ReportMeasurement> reportSegments(const Segmentation& s, const Volume& v,
                                              const Volume* overlay = nullptr,
                                              const std::string& overlayName = "");

// The slices (k of the volume: the series' own images) marked as key images, in the order
// marked, each once.
class KeyImageSet {
 public:
  const std::vector<int>& slices() const { return slices_; }
  bool contains(int k) const;
  // Marks K, or unmarks it when marked; returns whether it is marked now.
  bool toggle(int k);
  void clear();
  Notifier<> changed;

 private:
  std::vector<int> slices_;
};

// Whether PATH is FOLDER or lies under it (both made absolute and normal; links followed
// where they exist): results never go into the user's data folder.
bool insideFolder(const std::string& path, const std::string& folder);
// The folder of the open input (the input itself when it is a folder); "" for none.
std::string sourceFolder(const std::string& input);
// Throws Error (Output) when PATH lies inside the source folder of INPUT, saying what to do.
void refuseSourceFolder(const std::string& path, const std::string& input);

}  // namespace voxray
