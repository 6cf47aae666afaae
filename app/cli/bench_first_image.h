#pragma once
// voxray-cli bench --first-image (issue 38 part 1): the time from the command's start to the
// first image of a volume and to its full-resolution image, split by step (read, coarse
// level, its frame, device upload, empty-space tables, the full frame), with the process's
// peak resident memory against the volume's bytes.
#include <iosfwd>

#include "input_options.h"
#include "voxray/engine/render_params.h"

namespace voxray::cli {

struct FirstImageOptions {
  int coarseFactor = 4;  // 1: no coarse frame (the full frame is the first image)
  std::string device, storage = "auto";
  bool json = false;
};

// Loads INPUT, renders PARAMS from a coarse level first (unless the factor is 1), then from
// the full volume; prints the steps to OUT. Returns the command's exit code.
int benchFirstImage(const InputOptions& input, const RenderParams& params,
                    const FirstImageOptions& options, std::ostream& out);

}  // namespace voxray::cli
