#pragma once
// A segmentation as the session file's optional "segmentation" key: its grid, its segments
// and the label map as compressed text (label_map_text.h).
#include <nlohmann/json.hpp>

#include "voxray/io/segmentation.h"

namespace voxray {

nlohmann::ordered_json segmentationToJson(const Segmentation& s);
// Throws an input Error saying which part ("dims", "segments[2].label", "label-map") is wrong.
// Whether the grid is the volume's is checked when the session is applied (session_state.h).
Segmentation segmentationFromJson(const nlohmann::ordered_json& j);

}  // namespace voxray
