#pragma once
// A QIDO-RS match read from its DICOM JSON object (PS3.18 F.2), whatever the node sent: a
// value of the wrong JSON type reads as absent, never as an exception.
#include <nlohmann/json.hpp>

#include "voxray/io/pacs.h"

namespace voxray::pacs {

PacsMatch toMatch(const nlohmann::json& object);

}  // namespace voxray::pacs
