#pragma once
// What the tests that run a program (voxray-cli, the Python readers, dcmdump, dciodvfy) share:
// its exit code and what it printed, and a scratch folder per test for what it writes.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

namespace voxray::test {

struct CommandResult {
  int exitCode = -1;   // -1: it could not start, or a signal ended it (a crash, the time-out's)
  std::string output;  // its stdout, and its stderr where COMMAND joins it ("2>&1")
};

// Runs COMMAND through the shell and reads its output to the end.
inline CommandResult runCommand(const std::string& command) {
  CommandResult r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) r.output.append(buffer, n);
  const int status = pclose(pipe);
  if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
  return r;
}

// A fixture with a fresh folder under the system temp folder (PREFIX and a random number),
// removed with everything in it after the test.
class ScratchFolderTest : public ::testing::Test {
 protected:
  explicit ScratchFolderTest(const std::string& prefix) {
    std::random_device seed;
    dir_ = std::filesystem::temp_directory_path() / (prefix + std::to_string(seed()));
    std::filesystem::create_directories(dir_);
  }
  ~ScratchFolderTest() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

}  // namespace voxray::test
