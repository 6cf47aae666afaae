#pragma once
// The C interface of the MP4 module (libvoxray_mp4.so), which mp4_writer.cpp loads when a
// movie is first written. FFmpeg is not linked into the programs: its ~100 libraries (codecs,
// muxers, their own dependencies) were about half of every voxray-cli start, for commands
// that never write a movie (issue 39 item 8: pacs get within 1.2x curl). Plain C types
// across the boundary: no exception or C++ object crosses it.
#include <cstddef>
#include <cstdint>

extern "C" {

typedef struct VoxrayMp4 VoxrayMp4;

// Codes: 0 success; 1 (open: FFmpeg has no libx264 encoder); 2 another failure, with
// FFmpeg's reason in WHY (WHY_SIZE bytes, NUL-terminated).
// Starts an H.264 MP4 of WIDTH x HEIGHT RGBA frames at FPS and CRF in FILE (created);
// *OUT gets the writer, to be closed with voxray_mp4_close whatever happens.
int voxray_mp4_open(const char* file, int width, int height, double fps, int crf, VoxrayMp4** out,
                    char* why, size_t whySize);
// Encodes one WIDTH x HEIGHT RGBA8 frame.
int voxray_mp4_push(VoxrayMp4* movie, const uint8_t* rgba, char* why, size_t whySize);
// Drains the encoder, writes the index and closes FILE.
int voxray_mp4_finish(VoxrayMp4* movie, char* why, size_t whySize);
// Frees the writer (null: nothing); FILE stays as it is.
void voxray_mp4_close(VoxrayMp4* movie);
}
