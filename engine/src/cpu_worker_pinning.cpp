#include "cpu_worker_pinning.h"

#include <cstdlib>
#include <mutex>

#if defined(__linux__)
#include <sched.h>
#include <unistd.h>
#endif

namespace voxray {

bool everyWorkerCanTakeItsCpu(const bool* allowed, int allowedCount, int online) {
  if (online <= 0 || allowedCount < online) return false;
  for (int i = 0; i < online; ++i)
    if (!allowed[i]) return false;
  return true;
}

void pinCpuWorkersWhereSafe() {
  static std::once_flag once;  // a function's static: ready for the call below, before main
  std::call_once(once, [] {
#if defined(__linux__)
    if (std::getenv("POCL_AFFINITY") || std::getenv("POCL_CPU_MAX_CU_COUNT")) return;
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) != 0) return;
    const long online = sysconf(_SC_NPROCESSORS_ONLN);
    if (online <= 0 || online > CPU_SETSIZE) return;
    bool allowed[CPU_SETSIZE];
    for (int i = 0; i < CPU_SETSIZE; ++i) allowed[i] = CPU_ISSET(i, &set);
    if (everyWorkerCanTakeItsCpu(allowed, CPU_SETSIZE, int(online)))
      setenv("POCL_AFFINITY", "1", 0);
#endif
  });
}

namespace {

// setenv is unsafe while another thread reads the environment: a Qt test's watchdog thread
// crashed in getenv while a render thread's first OpenCL call set POCL_AFFINITY. Before main
// no thread of ours runs yet, so the decision is made there; the engine's own call before
// its first OpenCL call then finds it made.
[[maybe_unused]] const bool kDecidedBeforeMain = (pinCpuWorkersWhereSafe(), true);

}  // namespace

}  // namespace voxray
