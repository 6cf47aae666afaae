#pragma once
// The small real CT embedded in the binaries, which the workstation opens when started
// without a file: a CT of a plastic head phantom (Philips scanner, 256 x 256 x 28 at
// 0.9 x 0.9 x 5 mm, HU), from Chris Rorden's DICOM validation data, BSD-2-Clause.
// resources/sample/README.md says how it was made; the head phantom of phantom.h stays
// the tests' volume.
#include <string>

#include "voxray/io/volume.h"

namespace voxray {

// The input name that loadVolume opens as the sample (a name no file can clash with:
// "sample:" is not a path the user types).
inline constexpr const char* kSampleCtInput = "sample:head-phantom-ct";

// Throws Error (Internal) if the embedded data are damaged (a broken build).
Volume loadSampleCt();

// Where the sample comes from and under which licence, for the About box and --help.
std::string sampleCtAttribution();

}  // namespace voxray
