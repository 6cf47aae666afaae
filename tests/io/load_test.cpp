// loadVolume: the one entry point, with progress and cancellation.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>

#include "test_support.h"
#include "voxray/io/load.h"
#include "voxray/io/phantom.h"

namespace voxray {
namespace {

using testing::HasSubstr;

RawLayout ctHeadLayout() {
  RawLayout l;
  l.dims = {256, 256, 0};
  l.order = ByteOrder::Big;
  l.spacingMm = {1, 1, 2};
  return l;
}

TEST(Load, EmptyInputGivesThePhantom) {
  const Volume v = loadVolume("");
  EXPECT_EQ(v.dims, glm::ivec3(256));
  EXPECT_EQ(test::checksum(v), test::checksum(makeHeadPhantom()));
}

TEST(Load, RawWithProgress) {
  LoadOptions options;
  options.raw = ctHeadLayout();
  std::mutex m;
  double last = 0;
  int calls = 0;
  options.progress = [&](double fraction, const std::string&) {
    std::lock_guard lock(m);
    EXPECT_GE(fraction, 0.0);
    EXPECT_LE(fraction, 1.0);
    last = std::max(last, fraction);
    ++calls;
  };
  const Volume v = loadVolume(test::dataPath("stanford/CThead"), options);
  EXPECT_EQ(v.dims, glm::ivec3(256, 256, 113));
  EXPECT_EQ(storedRange(v).max, 3272);
  EXPECT_GE(calls, 113);
  EXPECT_EQ(last, 1.0);
}

TEST(Load, CancelStopsTheLoad) {
  LoadOptions options;
  options.raw = ctHeadLayout();
  std::atomic<bool> cancel{false};
  options.cancel = &cancel;
  options.progress = [&](double, const std::string&) { cancel = true; };
  // A cancellation, not an input error: the GUI shows no error box for it.
  EXPECT_THAT(test::errorMessage([&] { loadVolume(test::dataPath("stanford/CThead"), options); },
                                 Error::Kind::Cancelled),
              HasSubstr("loading cancelled"));
}

TEST(Load, MissingInput) {
  EXPECT_THAT(test::errorMessage([] { loadVolume("/nonexistent/scan"); }),
              HasSubstr("/nonexistent/scan: no such file or folder"));
}

TEST(Load, RawFileWithoutLayoutAsksForOne) {
  const std::string path = test::dataPath("raw/cranium-ct/cranium_256x256x108_s16le.raw");
  const std::string m = test::errorMessage([&] { loadVolume(path); });
  EXPECT_THAT(m, HasSubstr("cranium_256x256x108_s16le.raw: not a DICOM file"));
  EXPECT_THAT(m, HasSubstr("--raw-dims"));
}

}  // namespace
}  // namespace voxray
