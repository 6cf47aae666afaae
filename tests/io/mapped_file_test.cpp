// MappedFile: the file's bytes in place, and a read that survives the file shrinking under
// it (another program rewriting it) with false instead of a SIGBUS that ends the program.
#include "mapped_file.h"

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>

#include "test_support.h"

namespace voxray {
namespace {

std::string writeBytes(const test::TempDir& dir, size_t n) {
  const std::string path = dir.file("bytes.bin");
  std::ofstream out(path, std::ios::binary);
  for (size_t i = 0; i < n; ++i) out.put(char(i * 7 % 251));
  return path;
}

TEST(MappedFile, HoldsTheFilesBytes) {
  test::TempDir dir;
  const MappedFile f(writeBytes(dir, 3 * 4096 + 5));
  ASSERT_NE(f.data(), nullptr);
  ASSERT_EQ(f.size(), 3u * 4096 + 5);
  uint64_t sum = 0, expected = 0;
  EXPECT_TRUE(f.read([&] {
    for (size_t i = 0; i < f.size(); ++i) sum += f.data()[i];
  }));
  for (size_t i = 0; i < f.size(); ++i) expected += i * 7 % 251;
  EXPECT_EQ(sum, expected);
}

TEST(MappedFile, NothingToMapIsEmpty) {
  test::TempDir dir;
  const MappedFile missing(dir.file("missing.bin"));
  EXPECT_EQ(missing.data(), nullptr);
  EXPECT_EQ(missing.size(), 0u);
  bool ran = false;
  EXPECT_FALSE(missing.read([&] { ran = true; }));
  EXPECT_FALSE(ran);
  const MappedFile folder(dir.path().string());
  EXPECT_EQ(folder.data(), nullptr);
  const MappedFile empty(writeBytes(dir, 0));
  EXPECT_EQ(empty.data(), nullptr);
}

// The file is cut to one page while it is read: the read of its third page ends in false,
// and reads go on working (here and on the next file) afterwards.
TEST(MappedFile, AFileCutWhileReadIsFalseNotACrash) {
  test::TempDir dir;
  const std::string path = writeBytes(dir, 4 * 4096);
  const MappedFile f(path);
  ASSERT_NE(f.data(), nullptr);
  volatile uint8_t seen = 0;
  bool reachedEnd = false;
  EXPECT_FALSE(f.read([&] {
    std::filesystem::resize_file(path, 4096);
    seen = f.data()[2 * 4096];
    reachedEnd = true;
  }));
  EXPECT_FALSE(reachedEnd);
  EXPECT_TRUE(f.read([&] { seen = f.data()[100]; }));
  EXPECT_EQ(seen, uint8_t(100 * 7 % 251));
  const MappedFile again(writeBytes(dir, 8192));
  EXPECT_TRUE(again.read([&] { seen = again.data()[8191]; }));
  EXPECT_EQ(seen, uint8_t(8191 * 7 % 251));
}

// A bus error outside any guarded read is not swallowed: the program ends as it would have
// (by SIGBUS; in the sanitizer build the handler before ours is ASan's, which aborts).
bool endedByTheFault(int status) {
  return WIFSIGNALED(status) && (WTERMSIG(status) == SIGBUS || WTERMSIG(status) == SIGABRT);
}

TEST(MappedFileDeathTest, AFaultOutsideAGuardedReadStillEndsTheProgram) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  test::TempDir dir;
  const std::string path = writeBytes(dir, 4 * 4096);
  EXPECT_EXIT(
      {
        const MappedFile f(path);
        f.read([] {});  // the handler is installed
        std::filesystem::resize_file(path, 4096);
        volatile uint8_t b = f.data()[2 * 4096];
        (void)b;
        std::_Exit(0);
      },
      endedByTheFault, "");
}

}  // namespace
}  // namespace voxray
