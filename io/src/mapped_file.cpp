#include "mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csetjmp>
#include <csignal>
#include <mutex>

namespace voxray {
namespace {

// The thread's guarded read, if any: where it may fault and where to go back to.
struct Guard {
  const uint8_t* begin;
  const uint8_t* end;
  sigjmp_buf back;
};
thread_local Guard* tGuard = nullptr;
struct sigaction gPrevious {};

void onBusError(int signal, siginfo_t* info, void* context) {
  const auto* at = static_cast<const uint8_t*>(info->si_addr);
  if (Guard* g = tGuard; g && at >= g->begin && at < g->end) siglongjmp(g->back, 1);
  // Not ours: whatever handled SIGBUS before, or the default (the fault repeats and ends
  // the process as it would have without us).
  if (gPrevious.sa_flags & SA_SIGINFO) {
    gPrevious.sa_sigaction(signal, info, context);
  } else if (gPrevious.sa_handler != SIG_DFL && gPrevious.sa_handler != SIG_IGN) {
    gPrevious.sa_handler(signal);
  } else {
    struct sigaction fallback {};
    fallback.sa_handler = SIG_DFL;
    sigaction(SIGBUS, &fallback, nullptr);
  }
}

void installHandler() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction a {};
    a.sa_sigaction = onBusError;
    a.sa_flags = SA_SIGINFO | SA_NODEFER;
    sigemptyset(&a.sa_mask);
    sigaction(SIGBUS, &a, &gPrevious);
  });
}

}  // namespace

MappedFile::MappedFile(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  struct stat st {};
  if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    // Populated at once: a few page-table batches instead of a fault per 64 KiB.
    void* p = mmap(nullptr, size_t(st.st_size), PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (p != MAP_FAILED) {
      data_ = static_cast<const uint8_t*>(p);
      size_ = size_t(st.st_size);
    }
  }
  ::close(fd);
}

MappedFile::~MappedFile() {
  if (data_) munmap(const_cast<uint8_t*>(data_), size_);
}

bool MappedFile::read(const std::function<void()>& reads) const {
  if (!data_) return false;
  installHandler();
  Guard g{data_, data_ + size_, {}};
  Guard* const outer = tGuard;
  if (sigsetjmp(g.back, 1) != 0) {
    tGuard = outer;
    return false;
  }
  // READS must leave nothing to destroy when the jump skips its frames: the decoders'
  // loops over plain memory do.
  tGuard = &g;
  try {
    reads();
  } catch (...) {
    tGuard = outer;
    throw;
  }
  tGuard = outer;
  return true;
}

}  // namespace voxray
