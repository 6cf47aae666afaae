#pragma once
// A segmentation as the session file's optional "segmentation" key: its grid, its segments
// and the label map as compressed text (label_map_text.h).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "voxray/io/segmentation.h"

namespace voxray {

nlohmann::ordered_json segmentationToJson(const Segmentation& s);
// A segment's 3D display as the session writes it ("volume", "surface", "hidden"), and back
// (nullopt for another word). Sessions from before it have no key: "volume", as they showed.
std::string display3dName(Segment::Display3d d);
std::optional<Segment::Display3d> parseDisplay3d(const std::string& name);
// Throws an input Error saying which part ("dims", "segments[2].label", "label-map") is wrong.
// Whether the grid is the volume's is checked when the session is applied (session_state.h).
Segmentation segmentationFromJson(const nlohmann::ordered_json& j);

}  // namespace voxray
