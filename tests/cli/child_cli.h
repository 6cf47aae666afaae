#pragma once
// What the CLI tests that watch a child voxray-cli share: a run in a child process with its
// output and peak resident memory, and a CT-like ball written as raw int16. Needs VOXRAY_CLI
// (the program's path) defined by the test target.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace voxray::test {

struct ChildRun {
  int status = -1;
  long maxRssKiB = 0;
  std::string out;
};

// ARGS run as voxray-cli's arguments; stdout (and stderr with BOTH) captured, the child's
// peak RSS from wait4.
inline ChildRun runCli(const std::vector<std::string>& args, bool both = false) {
  int pipeFd[2];
  if (::pipe(pipeFd) != 0) return {};
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(pipeFd[1], 1);
    if (both) ::dup2(pipeFd[1], 2);
    ::close(pipeFd[0]);
    ::close(pipeFd[1]);
    std::vector<char*> argv{const_cast<char*>(VOXRAY_CLI)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(VOXRAY_CLI, argv.data());
    ::_exit(127);
  }
  ::close(pipeFd[1]);
  ChildRun r;
  char buf[4096];
  for (ssize_t n; (n = ::read(pipeFd[0], buf, sizeof buf)) > 0;) r.out.append(buf, size_t(n));
  ::close(pipeFd[0]);
  struct rusage use {};
  ::wait4(pid, &r.status, 0, &use);
  r.maxRssKiB = use.ru_maxrss;  // KiB on Linux
  return r;
}

// A little-endian int16 volume X x Y x Z: a CT-like ball (air -1000, skin 0, a bone shell
// 1000, brain 40 HU), each value plus OFFSET (1024: stored as a scanner's raw values).
inline void writeBall(const std::filesystem::path& path, int nx, int ny, int nz, int offset) {
  std::ofstream f(path, std::ios::binary);
  std::vector<int16_t> slice(size_t(nx) * size_t(ny));
  for (int z = 0; z < nz; ++z) {
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const double dx = (x - nx / 2.0) / (0.45 * nx), dy = (y - ny / 2.0) / (0.42 * ny),
                     dz = (z - nz / 2.0) / (0.47 * nz);
        const double r = dx * dx + dy * dy + dz * dz;
        const int hu = r < 0.77 ? 40 : r < 0.86 ? 1000 : r < 1.0 ? 0 : -1000;
        slice[size_t(y) * size_t(nx) + size_t(x)] = int16_t(hu + offset);
      }
    f.write(reinterpret_cast<const char*>(slice.data()), std::streamsize(slice.size() * 2));
  }
}

}  // namespace voxray::test
