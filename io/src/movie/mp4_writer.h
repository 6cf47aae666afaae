#pragma once
// The MP4 (H.264) half of openMovieWriter: FFmpeg stays inside io/src/movie.
#include <memory>
#include <string>

#include "voxray/io/movie_writer.h"

namespace voxray {

std::unique_ptr<MovieWriter> openMp4Writer(const std::string& path, const MovieSettings& s);

}  // namespace voxray
