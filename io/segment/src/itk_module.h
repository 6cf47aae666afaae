#pragma once
// The interface of the ITK module (libvoxray_itk.so), which itk_loader.cpp loads on the
// first ITK operation (islands, median, closing, opening, ITK's fill holes). ITK is not
// linked into the programs: its libraries were ~3 ms of every voxray-cli start for commands
// that never use them (issue 39 item 8). Built in the same tree with the same compiler and
// standard library, so the blocks pass by pointer; no exception crosses the boundary.
#include <string>

#include "segment_itk.h"

extern "C" {

enum VoxrayItkOperation {
  kVoxrayItkIslands,
  kVoxrayItkMedian,
  kVoxrayItkClosing,
  kVoxrayItkOpening,
  kVoxrayItkFillHoles
};

// OPERATION on *BLOCK with RADIUS (median, closing, opening) or FULLY_CONNECTED (islands,
// into *ISLANDS). Returns 0, or 1 with ITK's reason in *WHY.
int voxray_itk_run(int operation, voxray::itk_ops::Block* block, const int radius[3],
                   int fullyConnected, voxray::itk_ops::Islands* islands, std::string* why);
}
