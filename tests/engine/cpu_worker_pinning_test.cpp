// PoCL's worker threads are pinned one per CPU where that is safe (cpu_worker_pinning.h):
// unpinned, they sometimes shared a core and iso frames took 15-19 ms instead of 11-13.
#include <gtest/gtest.h>

#include <dirent.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <string>

#include "cpu_worker_pinning.h"
#include "voxray/engine/cl_context.h"

namespace voxray {
namespace {

TEST(CpuWorkerPinning, OnlyWhenEveryWorkerCanTakeItsCpu) {
  const bool all[4] = {true, true, true, true};
  EXPECT_TRUE(everyWorkerCanTakeItsCpu(all, 4, 4));
  EXPECT_TRUE(everyWorkerCanTakeItsCpu(all, 4, 2));      // more allowed than online: fine
  const bool taskset23[4] = {false, false, true, true};  // taskset -c 2,3
  EXPECT_FALSE(everyWorkerCanTakeItsCpu(taskset23, 4, 4));
  const bool hole[4] = {true, false, true, true};
  EXPECT_FALSE(everyWorkerCanTakeItsCpu(hole, 4, 4));
  EXPECT_FALSE(everyWorkerCanTakeItsCpu(all, 4, 8));  // online CPUs beyond the mask
  EXPECT_FALSE(everyWorkerCanTakeItsCpu(all, 4, 0));
}

// The CPUs thread TASK of this process may run on, as "0-1" or "1".
std::string allowedList(const std::string& task) {
  std::ifstream status("/proc/self/task/" + task + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("Cpus_allowed_list:", 0) == 0) {
      const size_t at = line.find_first_not_of(" \t", 18);
      return at == std::string::npos ? std::string() : line.substr(at);
    }
  return {};
}

// Why this process's PoCL workers are not to be pinned, or nothing.
std::string whyNoPinning() {
  const char* set = std::getenv("POCL_AFFINITY");
  if ((set && std::string(set) != "1") || std::getenv("POCL_CPU_MAX_CU_COUNT"))
    return "POCL_AFFINITY or POCL_CPU_MAX_CU_COUNT set by the user";
  cpu_set_t mask;
  CPU_ZERO(&mask);
  const long online = sysconf(_SC_NPROCESSORS_ONLN);
  if (sched_getaffinity(0, sizeof(mask), &mask) != 0 || online < 2 || CPU_COUNT(&mask) < online)
    return "one CPU, or this process is limited to some CPUs: no pinning";
  return {};
}

TEST(CpuWorkerPinning, PoclWorkersRunOnePerCpu) {
  if (const std::string why = whyNoPinning(); !why.empty()) GTEST_SKIP() << why;
  ClContext ctx("cpu");
  if (ctx.device().platform != "Portable Computing Language")
    GTEST_SKIP() << "the CPU device is not PoCL's";
  std::set<std::string> pinned;
  DIR* tasks = opendir("/proc/self/task");
  ASSERT_NE(tasks, nullptr);
  while (dirent* e = readdir(tasks)) {
    if (e->d_name[0] == '.') continue;
    const std::string cpus = allowedList(e->d_name);
    if (cpus.find_first_of(",-") == std::string::npos) pinned.insert(cpus);
  }
  closedir(tasks);
  std::set<std::string> expected;
  for (unsigned i = 0; i < ctx.device().computeUnits; ++i) expected.insert(std::to_string(i));
  EXPECT_EQ(pinned, expected);
  const char* now = std::getenv("POCL_AFFINITY");
  EXPECT_STREQ(now ? now : "", "1");
}

// The decision is made before main, not at the engine's first OpenCL call: setenv there
// raced with other threads' getenv (a Qt test's watchdog crashed in getenv while a render
// thread made the first context). A fresh process of this binary, started without
// POCL_AFFINITY, has it set when its one test starts, before anything made a context.
TEST(CpuWorkerPinning, DecidedBeforeMainInAFreshProcess) {
  if (std::getenv("VOXRAY_PINNING_CHILD")) {
    const char* now = std::getenv("POCL_AFFINITY");
    std::cout << "child POCL_AFFINITY=[" << (now ? now : "") << "]\n";
    return;
  }
  if (const std::string why = whyNoPinning(); !why.empty()) GTEST_SKIP() << why;
  // As the other tests run commands (popen); `env -u` starts it without POCL_AFFINITY.
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  FILE* child = popen(("env -u POCL_AFFINITY VOXRAY_PINNING_CHILD=1 '" + self +
                       "' --gtest_filter=CpuWorkerPinning.DecidedBeforeMainInAFreshProcess")
                          .c_str(),
                      "r");
  ASSERT_NE(child, nullptr);
  std::string text;
  char buf[4096];
  for (size_t n; (n = fread(buf, 1, sizeof buf, child)) > 0;) text.append(buf, n);
  const int status = pclose(child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << text;
  EXPECT_NE(text.find("child POCL_AFFINITY=[1]"), std::string::npos) << text;
}

}  // namespace
}  // namespace voxray
