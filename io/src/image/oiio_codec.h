#pragma once
// The C interface of the OpenImageIO module (libvoxray_oiio.so), which image_io.cpp loads on
// the first image read or written. OpenImageIO is not linked into the programs: its 260
// libraries (OpenCV, FFmpeg, GDCM, libheif...) took about 55 % of every voxray-cli start
// (relocations and their static constructors, 0.3 s of CPU on a loaded 2-core Xeon) for
// commands that never touch an image (issue 39 item 8: pacs get within 1.2x curl). Plain C
// types across the boundary: no exception or C++ object crosses it.
#include <cstddef>
#include <cstdint>

extern "C" {

// Each returns 0 on success; otherwise 1 (the format is not known for the file's extension;
// READ: the file cannot be opened), 2 (another failure) or 3 (READ: the image has no pixels),
// with OpenImageIO's reason in WHY (WHY_SIZE bytes, NUL-terminated).
// Writes an RGBA8 image to FILE (EXR as half floats).
int voxray_oiio_write(const char* file, int width, int height, const uint8_t* rgba, char* why,
                      size_t whySize);
// Reads PATH as 8-bit channels: ALLOCATE(CONTEXT, width, height, channels) returns where
// width * height * channels bytes go (null: nothing is read, 2 is returned).
typedef uint8_t* (*VoxrayOiioAllocate)(void* context, int width, int height, int channels);
int voxray_oiio_read(const char* path, VoxrayOiioAllocate allocate, void* context, char* why,
                     size_t whySize);
}
