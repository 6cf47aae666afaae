#pragma once
// The interface of the mesh module (libvoxray_mesh.so), which mesh_loader.cpp loads on the
// first surface made or mesh file written. VTK is not linked into the programs: its 30-odd
// libraries (~200,000 relocations) were about 11 ms of every voxray-cli start, a third of the
// dynamic linker's work, for commands that never make a surface (issue 39 item 8: pacs get
// within 1.2x curl). The module is built in the same tree with the same compiler and standard
// library, so Voxray's own types pass by pointer; no exception crosses the boundary: an error
// comes back as its kind (voxray::Error::Kind) and message.
#include <cstdint>
#include <string>
#include <vector>

#include "voxray/io/mesh_file.h"
#include "voxray/io/segment_mesh.h"
#include "voxray/io/segmentation.h"

extern "C" {

// Each returns 0, or 1 with the error's kind in *KIND and its message in *WHY.
// makeSurface(*S, LABEL, *OPTIONS, TIMINGS) into *OUT.
int voxray_mesh_surface(const voxray::Segmentation* s, uint8_t label,
                        const voxray::SurfaceOptions* options, voxray::SurfaceTimings* timings,
                        voxray::SegmentSurface* out, int* kind, std::string* why);
// writeMeshFile(PATH, *S, *LABELS, *OPTIONS).
int voxray_mesh_write(const char* path, const voxray::Segmentation* s,
                      const std::vector<uint8_t>* labels, const voxray::MeshFileOptions* options,
                      int* kind, std::string* why);
}
