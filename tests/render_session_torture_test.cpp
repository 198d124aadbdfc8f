// Rapid edits against a running render session from several threads at once (what a user
// dragging an object while a script edits lights would do): thousands of object moves, light
// edits (whole-scene replacements), option changes and cancellations. The session must not
// deadlock (every wait is bounded; a watchdog aborts a hung run), must not crash, and must
// never deliver a frame of an older scene version after one of a newer version. Run it under
// TSan too (INLAY_SANITIZE=thread, see README.md).
#include "render_test_scenes.h"
#include "test_support.h"

#include "inlay/render/session.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <random>
#include <thread>

namespace inlay {
namespace {

using Clock = std::chrono::steady_clock;

// Checks each frame as it arrives (on the render thread) and keeps counts only.
class OrderChecker : public FrameSink {
 public:
  void onFrame(std::shared_ptr<const RenderFrame> frame) override {
    std::lock_guard<std::mutex> lock(mutex_);
    ++frames_;
    if (frame->sceneVersion < last_) ++backwards_;
    if (!frame->withObjects.empty() && !test::allFinite(frame->withObjects)) ++nonFinite_;
    last_ = std::max(last_, frame->sceneVersion);
    lastFinal_ = frame->final;
    lastVersion_ = frame->sceneVersion;
  }
  struct Counts {
    long frames = 0, backwards = 0, nonFinite = 0;
    uint64_t lastVersion = 0;
    bool lastFinal = false;
  };
  Counts counts() {
    std::lock_guard<std::mutex> lock(mutex_);
    return {frames_, backwards_, nonFinite_, lastVersion_, lastFinal_};
  }

 private:
  std::mutex mutex_;
  long frames_ = 0, backwards_ = 0, nonFinite_ = 0;
  uint64_t last_ = 0, lastVersion_ = 0;
  bool lastFinal_ = false;
};

RenderScene tortureScene(double lightPower) {
  RenderScene s = test::roomScene(test::testCamera(40, 30, 70, 1.3, -10), RoomBox{}, 0.6);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.6, -2), Vec3(0.4, 0, 0), Vec3(0, 0, 0.4), Vec3::Constant(lightPower)));
  for (int k = 0; k < 2; ++k) {
    InsertedObject o;
    o.meshObject = test::sphereMesh(0.3, 8, 16);
    o.worldFromObject = test::translation(Vec3(-0.4 + 0.8 * k, 0.3, -2.5));
    s.objects.push_back(o);
  }
  return s;
}

// Aborts the process when `seconds` pass before disarm(): a deadlock fails loudly instead of
// hanging ctest.
class Watchdog {
 public:
  explicit Watchdog(double seconds)
      : thread_([this, seconds] {
          std::unique_lock<std::mutex> lock(mutex_);
          if (!cv_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return done_; })) {
            std::fprintf(stderr, "render session torture test: no progress for %.0f s (deadlock)\n",
                         seconds);
            std::abort();
          }
        }) {}
  ~Watchdog() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    cv_.notify_all();
    thread_.join();
  }

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  bool done_ = false;
  std::thread thread_;
};

TEST(SessionTorture, RapidEditsFromManyThreadsKeepFramesInOrder) {
  Watchdog watchdog(240);
  OrderChecker sink;
  SessionOptions opt;
  opt.targetSpp = 64;
  opt.threads = 2;
  RenderSession session(&sink, opt);
  session.setScene(tortureScene(5));

  // Bursts with short pauses, so frames are delivered between edits (a storm with no pause
  // would only test cancellation).
  constexpr int kMovesPerThread = 2000, kLightEdits = 150, kCancels = 600;
  constexpr int kMovers = 2;  // threads moving the objects; one more edits lights, one cancels
  std::vector<std::thread> threads;
  threads.reserve(kMovers + 2);
  for (int t = 0; t < kMovers; ++t)
    threads.emplace_back([&, t] {
      std::mt19937 rng(100 + t);
      std::uniform_real_distribution<double> x(-0.8, 0.8);
      for (int i = 0; i < kMovesPerThread; ++i) {
        session.setObjectTransform(size_t(t), test::translation(Vec3(x(rng), 0.3, -2.5)));
        if (i % 8 == 0) std::this_thread::sleep_for(std::chrono::microseconds(500 + 300 * t));
      }
    });
  threads.emplace_back([&] {
    for (int i = 0; i < kLightEdits; ++i) {
      session.setScene(tortureScene(2 + i % 7));
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      if (i % 10 == 0) {
        SessionOptions o = opt;
        o.targetSpp = 16 + i % 48;
        session.setOptions(o);
      }
    }
  });
  threads.emplace_back([&] {
    for (int i = 0; i < kCancels; ++i) {
      session.cancel();
      (void)session.busy();
      (void)session.waitUntilDone(0.002);
      std::this_thread::yield();
    }
  });
  const auto t0 = Clock::now();
  for (std::thread& th : threads) th.join();
  const double editSeconds = std::chrono::duration<double>(Clock::now() - t0).count();

  // A last edit after the storm: it must render to its final frame.
  const uint64_t last = session.setObjectTransform(0, test::translation(Vec3(0, 0.3, -2.5)));
  ASSERT_TRUE(session.waitUntilDone(120)) << "the last edit never finished";
  const OrderChecker::Counts c = sink.counts();
  std::printf("[ torture ] %d moves, %d light edits, %d cancels in %.2f s; %ld frames delivered\n",
              2 * kMovesPerThread, kLightEdits, kCancels, editSeconds, c.frames);
  EXPECT_GT(c.frames, 10);
  EXPECT_EQ(c.backwards, 0) << "a frame of an older edit came after a newer one";
  EXPECT_EQ(c.nonFinite, 0);
  EXPECT_EQ(c.lastVersion, last);
  EXPECT_TRUE(c.lastFinal);
  EXPECT_FALSE(session.busy());
}

// Destroying a session in the middle of an edit storm returns promptly.
TEST(SessionTorture, DestructorDuringEditStorm) {
  Watchdog watchdog(120);
  OrderChecker sink;
  SessionOptions opt;
  opt.targetSpp = 1 << 20;
  opt.threads = 2;
  auto session = std::make_unique<RenderSession>(&sink, opt);
  session->setScene(tortureScene(5));
  std::atomic<bool> stop{false};
  std::thread editor([&] {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> x(-0.8, 0.8);
    while (!stop) session->setObjectTransform(1, test::translation(Vec3(x(rng), 0.3, -2.5)));
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  stop = true;
  editor.join();
  const auto t0 = Clock::now();
  session.reset();
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  EXPECT_LT(ms, 2000.0);
  EXPECT_EQ(sink.counts().backwards, 0);
}

}  // namespace
}  // namespace inlay
