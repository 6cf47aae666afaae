#pragma once
// INPUT's flags, declared once for voxray-cli and the workstation's command line: the raw
// layout (--raw-dims, --raw-type, ...) and the DICOM series. Each front end lists them as
// options and hands what the user gave to loadOptionsFromFlags.
#include <map>
#include <string>
#include <vector>

#include "voxray/engine/param_spec.h"
#include "voxray/io/load.h"

namespace voxray {

using InputFlagSpec = Spec<LoadOptions>;
const std::vector<InputFlagSpec>& inputFlagSpecs();
// The spec of KEY; throws Error (Input) for an unknown key.
const InputFlagSpec& findInputFlagSpec(const std::string& key);

// The load options for the flags GIVEN (by key, without "--"). Throws Error (Input) for a
// bad value, an unknown key, or raw flags without --raw-dims.
LoadOptions loadOptionsFromFlags(const std::map<std::string, std::string>& given);
// The flags that give O back through loadOptionsFromFlags (those with a value), by key.
std::map<std::string, std::string> flagsFromLoadOptions(const LoadOptions& o);

}  // namespace voxray
