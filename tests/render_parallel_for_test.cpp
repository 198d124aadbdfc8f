// inlay::parallelFor (modeling/include/inlay/modeling/parallel.h): every index is visited once
// per loop, and the caller reuses its stack right after loops whose last chunk a TBB worker
// often finishes (the pattern behind the TSan reports acquireTbbFrames removes). Under TSan
// (INLAY_SANITIZE=thread, halt_on_error) a report fails the test; but in this short binary TSan
// can still restore the worker's stack, which contains libtbb, so tsan.supp's race:libtbb.so
// would hide a regression here: the long studio runs (README's TSan table) are the real check.
#include "inlay/modeling/parallel.h"

#include <gtest/gtest.h>

#include <tbb/blocked_range.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace inlay {
namespace {

// Writes over the stack below the caller, where tbb::parallel_for's frames were.
[[gnu::noinline]] int scribbleStack(int seed) {
  volatile char bytes[4096];
  for (int i = 0; i < 4096; ++i) bytes[i] = char(seed + i);
  return bytes[seed & 4095];
}

TEST(ParallelFor, VisitsEveryIndexOnceAndTheStackIsReusableAfterward) {
  constexpr int kSize = 64, kLoops = 1500;
  std::vector<int> visits(kSize, 0);
  int scribbled = 0;
  for (int loop = 0; loop < kLoops; ++loop) {
    parallelFor(tbb::blocked_range<int>(0, kSize, 1), [&](const tbb::blocked_range<int>& r) {
      for (int i = r.begin(); i < r.end(); ++i) ++visits[i];
      // The upper half is slow, so a worker (not the caller) often finishes the loop.
      if (r.begin() >= kSize / 2) std::this_thread::sleep_for(std::chrono::microseconds(20));
    });
    scribbled += scribbleStack(loop);
  }
  for (int i = 0; i < kSize; ++i) ASSERT_EQ(visits[i], kLoops) << "index " << i;
  EXPECT_NE(scribbled, 0);
}

// runAlongside (parallel.h): `here` runs on the calling thread, `alongside` once, both finished
// when it returns, their parallel loops complete; with a free TBB worker they overlap (`here`
// waits for `alongside` to start, which one after the other would never see), and what
// `alongside` wrote is the caller's to read afterwards (the join TSan sees).
TEST(ParallelFor, RunAlongsideRunsBothSideBySideAndHereOnTheCallingThread) {
  constexpr int kSize = 256;
  for (int round = 0; round < 20; ++round) {
    std::vector<int> a(kSize, 0), b(kSize, 0);
    std::atomic<bool> alongsideStarted{false};
    bool sawAlongside = false;
    int hereRuns = 0, alongsideRuns = 0;
    std::thread::id hereThread;
    const auto loop = [](std::vector<int>& v) {
      parallelFor(tbb::blocked_range<int>(0, kSize, 8), [&](const tbb::blocked_range<int>& r) {
        for (int i = r.begin(); i < r.end(); ++i) v[size_t(i)] += i;
      });
    };
    runAlongside(
        [&] {
          ++hereRuns;
          hereThread = std::this_thread::get_id();
          const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
          while (!alongsideStarted.load() && std::chrono::steady_clock::now() < until)
            std::this_thread::sleep_for(std::chrono::microseconds(50));
          sawAlongside = alongsideStarted.load();
          loop(a);
        },
        [&] {
          ++alongsideRuns;
          alongsideStarted.store(true);
          loop(b);
        });
    EXPECT_EQ(hereThread, std::this_thread::get_id());
    ASSERT_EQ(hereRuns, 1);
    ASSERT_EQ(alongsideRuns, 1);
    for (int i = 0; i < kSize; ++i) ASSERT_TRUE(a[size_t(i)] == i && b[size_t(i)] == i) << i;
    if (tbb::this_task_arena::max_concurrency() >= 2) {
      EXPECT_TRUE(sawAlongside) << round;
    }
    scribbleStack(round);
  }
}

}  // namespace
}  // namespace inlay
