#pragma once
// voxray-cli bench --stall: the workstation's frames around the end of a drag, replayed on
// one thread with real frames and wall-clock waits (issue 16). The 3D view's render thread
// renders the newest request only, so a drag keeps it busy frame after frame; the mouse's
// last move comes as the last drag frame is asked for. The scheduler waits SETTLEMS after
// that move, then asks for the sharp frame, whole or in bands (ui/study/refine_bands.h).
// Measured: the largest gap between frames shown from the last drag frame to the finished
// sharp frame ("rest"), and, when the drag resumes RESUMEMS after the sharp frame was asked
// for, the wait from that move to its drag frame ("resume": the band or whole frame in
// flight finishes first; a banded refinement abandons the bands left).
#include <string>
#include <vector>

#include "voxray/engine/orbit.h"
#include "voxray/engine/raycaster.h"

namespace voxray::cli {

struct StallCase {
  std::string name;  // "before: whole, settle 150 ms"
  int settleMs = 150;
  int bands = 1;  // 1: the whole frame; else about this many bands (refineBands)
};

struct StallFigures {
  double restGapMs = 0;     // largest gap between frames shown, last drag frame to sharp
  double sharpDoneMs = 0;   // the last drag frame to the whole sharp frame shown
  double resumeWaitMs = 0;  // a move during the refinement to its drag frame shown
  // The same two in this process's CPU time (the resume's from the sharp frame's request)
  double restGapCpuMs = 0, resumeCpuMs = 0;
  double sharpCpuMs = 0;  // the sharp frame's CPU time, whole or all its bands
};

// One replay of CASE: DRAGFRAMES drag frames (DRAG, 2-degree steps of ORBIT), then the rest.
StallFigures replayStall(Raycaster& rc, const RenderParams& drag, const RenderParams& sharp,
                         const StallCase& c, Orbit orbit, int dragFrames, int resumeMs);

// The cases "before" (the whole frame after 150 ms, as the scheduler did), "after" (the
// 3D view's bands after its 60 ms) and twice as many bands, REPEATS times each alternately;
// prints medians.
void printStallReplay(Raycaster& rc, const RenderParams& drag, const RenderParams& sharp,
                      Orbit orbit, int repeats);

}  // namespace voxray::cli
