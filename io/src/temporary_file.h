#pragma once
// Hidden temporary names beside a target, for writes that must appear whole or not at all
// (images, movies): written there, then renamed.
#include <filesystem>

namespace voxray {

// Unique per process and call, with the target's extension kept so that writers choosing
// the format by extension still see it: "shot.png" -> ".shot.tmp4711-3.png".
std::filesystem::path temporaryBeside(const std::filesystem::path& target);

}  // namespace voxray
