#pragma once
// PoCL's CPU device runs kernels on one worker thread per core. Left to the scheduler, the
// workers sometimes share a core for part of a frame: on a 2-core Xeon about one iso run in
// four took 15-19 ms a frame instead of 11-13, with three times the thread migrations
// (docs/bench/README.md, Session 11). PoCL pins worker i to CPU i when POCL_AFFINITY is set.

namespace voxray {

// Asks PoCL to pin its workers (sets POCL_AFFINITY=1) unless the user set POCL_AFFINITY or
// POCL_CPU_MAX_CU_COUNT, or this process may not run on every online CPU 0..n-1 (a cpuset
// or taskset), where a worker would ask for a CPU it may not use (upstream PoCL checks that
// call and may abort; Debian's 3.1 rendered under `taskset -c 1` with it set). Runs once,
// before main (the engine's static initialisation: setenv is only safe while no other
// thread reads the environment); later calls do nothing.
void pinCpuWorkersWhereSafe();

// Whether a process allowed on ALLOWED CPUs (a bit per CPU, ALLOWED[i] for CPU i) with
// ONLINE CPUs online may pin worker i to CPU i for every worker.
bool everyWorkerCanTakeItsCpu(const bool* allowed, int allowedCount, int online);

}  // namespace voxray
