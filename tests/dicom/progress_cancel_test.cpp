// Parallel decode reports progress and honours cancellation.
#include <atomic>
#include <mutex>

#include "test_data.h"

namespace voxray {
namespace {

using test::dicomPath;

TEST(DicomProgress, ReportsUpToCompletion) {
  std::mutex m;
  std::vector<double> seen;
  LoadOptions o;
  o.progress = [&](double f, const std::string&) {
    std::lock_guard lock(m);
    seen.push_back(f);
  };
  importDicom(dicomPath("ct-visible-human-pelvis"), o);
  ASSERT_GT(seen.size(), 150u);  // one per slice at least
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);
  for (double f : seen) {
    EXPECT_GE(f, 0.0);
    EXPECT_LE(f, 1.0);
  }
}

TEST(DicomProgress, CancelStopsTheLoad) {
  std::atomic<bool> cancel{false};
  std::atomic<int> decoded{0};
  LoadOptions o;
  o.cancel = &cancel;
  o.progress = [&](double, const std::string& what) {
    if (what.rfind("Decoding", 0) == 0 && ++decoded == 5) cancel = true;
  };
  try {
    importDicom(dicomPath("ct-visible-human-pelvis"), o);
    FAIL() << "a cancelled load must throw";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Cancelled) << "a cancellation is not an input error";
    EXPECT_TRUE(isCancellation(e));
    EXPECT_NE(std::string(e.what()).find("cancelled"), std::string::npos);
  }
  EXPECT_LT(decoded.load(), 150);
}

TEST(DicomProgress, CancelledBeforeTheStartReportsCancelled) {
  std::atomic<bool> cancel{true};
  int reports = 0;
  LoadOptions o;
  o.cancel = &cancel;
  o.progress = [&](double, const std::string&) { ++reports; };
  try {
    listDicomSeries(dicomPath("ct-visible-human-pelvis"), o);
    FAIL() << "a cancelled listing must throw";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Cancelled) << e.what();
  }
  EXPECT_EQ(reports, 0) << "no header was read";
}

}  // namespace
}  // namespace voxray
