#pragma once
// Movies written one frame at a time (never the whole movie in memory): MP4 with H.264
// through FFmpeg's libraries (libx264 inside Debian's libavcodec), or a numbered PNG
// sequence through writeImage. Nothing appears under a final name before finish(): MP4 goes
// to a hidden temporary file beside the target and the frames of a sequence to hidden
// temporary names, renamed at the end. A writer destroyed before finish() (a cancel, an
// error) removes everything it wrote.
#include <memory>
#include <string>
#include <vector>

#include "voxray/io/image.h"

namespace voxray {

enum class MovieFormat { Mp4, ImageSequence };

// Which format PATH asks for: ".mp4" is MP4; a pattern with one integer conversion
// ("frames/%04d.png") or a folder (an existing one, or a path ending in "/") is a PNG
// sequence. Throws Error (Output) for anything else, saying what is accepted.
MovieFormat movieFormat(const std::string& path);

struct MovieSize {
  int width = 0;
  int height = 0;
};

// The frame size FORMAT stores for a requested size. H.264 in 4:2:0 (the chroma every
// player decodes) needs even sizes: MP4 rounds an odd width or height up by one, so frames
// are rendered one pixel larger there rather than padded or cropped. Sequences keep it.
MovieSize movieFrameSize(MovieFormat format, MovieSize requested);

// The files a movie of FRAMES frames at PATH ends as (one for MP4; one per frame for a
// sequence, numbered from 0; a folder gets "0000.png", ... with at least four digits), so
// that a caller can refuse or ask before replacing any of them.
std::vector<std::string> movieFiles(const std::string& path, int frames);

struct MovieSettings {
  MovieSize size;  // every frame pushed must have this size (movieFrameSize of it)
  int frames = 0;  // how many frames will be pushed (the sequence's numbering)
  double fps = 25.0;
  // H.264 constant rate factor (0 lossless ... 51). At 18 decoded frames of the phantom
  // measured 47-49 dB PSNR against render's PNG (tests/cli/movie_test.cpp asserts 40).
  int crf = 18;
};

class MovieWriter {
 public:
  virtual ~MovieWriter() = default;  // without finish(): removes what was written
  // Encodes or writes one frame. Throws Error (Output).
  virtual void push(const Image& frame) = 0;
  // Flushes and moves the result under its final name(s). Throws Error (Output).
  virtual void finish() = 0;
};

// Throws Error (Output) for a bad path or size, a folder that does not exist, or an FFmpeg
// without an H.264 encoder (saying to write a PNG sequence instead).
std::unique_ptr<MovieWriter> openMovieWriter(const std::string& path, const MovieSettings& s);

}  // namespace voxray
