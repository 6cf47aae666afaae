// MP4 writing for lean builds configured with VOXRAY_WITH_MP4=OFF (benchmarks carried to
// machines without FFmpeg's libraries): PNG frame movies still work.
#include "mp4_writer.h"
#include "voxray/io/error.h"

namespace voxray {

std::unique_ptr<MovieWriter> openMp4Writer(const std::string& path, const MovieSettings&) {
  throw outputError(path +
                    ": this build writes no MP4 (configured with VOXRAY_WITH_MP4=OFF); "
                    "write PNG frames to a folder, or use a default build");
}

}  // namespace voxray
