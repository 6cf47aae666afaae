// voxray::parallelFor, the one parallel loop: every index once, its error rule and its
// cancellation.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "voxray/io/error.h"
#include "voxray/io/parallel.h"

namespace voxray {
namespace {

TEST(ParallelFor, RunsEveryIndexOnce) {
  std::vector<std::atomic<int>> runs(1000);
  parallelFor(runs.size(), [&](size_t i) { ++runs[i]; });
  for (size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].load(), 1) << i;
  parallelFor(0, [](size_t) { FAIL() << "no index in an empty range"; });
}

TEST(ParallelFor, RethrowsTheLowestFailingIndexOnTheCaller) {
  // Indices 300 and 700 throw: whatever the scheduling, the caller sees 300, the error a
  // serial loop would have stopped at.
  for (int round = 0; round < 20; ++round) {
    try {
      parallelFor(1000, [](size_t i) {
        if (i == 300 || i == 700) throw inputError("slice " + std::to_string(i));
      });
      FAIL() << "the worker's error must reach the caller";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), "slice 300");
      EXPECT_EQ(e.kind(), Error::Kind::Input);  // the worker's own exception, not a copy
    }
  }
}

TEST(ParallelFor, AnErrorStopsHandingOutWork) {
  // The first index throws at once; the others take a while, so only the ones already
  // handed out (at most one per thread) run before everything stops.
  std::atomic<int> ran{0};
  std::atomic<int> running{0};
  const size_t count = 10000;
  EXPECT_THROW(parallelFor(count,
                           [&](size_t i) {
                             ++running;
                             if (i == 0) {
                               --running;
                               throw std::runtime_error("first");
                             }
                             ++ran;
                             std::this_thread::sleep_for(std::chrono::microseconds(200));
                             --running;
                           }),
               std::runtime_error);
  EXPECT_EQ(running.load(), 0) << "every worker has stopped when the error arrives";
  EXPECT_LT(ran.load(), int(count) / 10);
}

TEST(ParallelFor, CancelStopsHandingOutWorkAndReturns) {
  std::atomic<bool> cancel{false};
  std::atomic<int> ran{0};
  const size_t count = 10000;
  parallelFor(
      count,
      [&](size_t i) {
        ++ran;
        if (i == 5) cancel = true;
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      },
      &cancel);
  EXPECT_GE(ran.load(), 6);
  EXPECT_LT(ran.load(), int(count) / 10);
  // A flag already set runs nothing.
  ran = 0;
  parallelFor(
      count, [&](size_t) { ++ran; }, &cancel);
  EXPECT_EQ(ran.load(), 0);
}

}  // namespace
}  // namespace voxray
