// The render schedule as a pure value, and the progressive session: frames arrive in order,
// an edit cancels the running wave quickly, time limits, cancel() and shutdown.
#include "render_test_scenes.h"
#include "test_support.h"

#include "inlay/render/composite.h"
#include "inlay/render/session.h"

#include <chrono>
#include <condition_variable>
#include <mutex>

namespace inlay {
namespace {

using Clock = std::chrono::steady_clock;

TEST(Schedule, CoarseThenDoublingWaves) {
  const std::vector<RenderWork> expected = {{0, 1, 8}, {0, 1, 4}, {0, 1, 2}, {0, 1, 1}, {1, 1, 1},
                                            {2, 2, 1}, {4, 4, 1}, {8, 8, 1}, {16, 4, 1}};
  EXPECT_EQ(makeRenderSchedule(20, 8, 16), expected);
  // Capped waves, no preview, exact total.
  const auto s = makeRenderSchedule(100, 1, 16);
  int next = 0;
  for (const RenderWork& w : s) {
    EXPECT_EQ(w.resolutionDivider, 1);
    EXPECT_EQ(w.firstSample, next);
    EXPECT_LE(w.sampleCount, 16);
    EXPECT_GE(w.sampleCount, 1);
    next += w.sampleCount;
  }
  EXPECT_EQ(next, 100);
  EXPECT_EQ(s.size(), 11u);  // 1 1 2 4 8 16 16 16 16 16 4
  EXPECT_TRUE(makeRenderSchedule(0, 1).empty());
  EXPECT_EQ(makeRenderSchedule(1, 3, 16), (std::vector<RenderWork>{{0, 1, 3}, {0, 1, 1}}));
}

class Collector : public FrameSink {
 public:
  void onFrame(std::shared_ptr<const RenderFrame> frame) override {
    std::lock_guard<std::mutex> lock(mutex_);
    frames_.push_back({std::move(frame), Clock::now()});
    cv_.notify_all();
  }
  struct Entry {
    std::shared_ptr<const RenderFrame> frame;
    Clock::time_point at;
  };
  // Waits until pred(frames) or the timeout; returns pred's last value.
  template <class Pred>
  bool waitFor(Pred pred, double seconds) {
    std::unique_lock<std::mutex> lock(mutex_);
    return cv_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return pred(frames_); });
  }
  std::vector<Entry> frames() {
    std::lock_guard<std::mutex> lock(mutex_);
    return frames_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  std::vector<Entry> frames_;
};

RenderScene sessionScene(int w, int h) {
  RenderScene s = test::roomScene(test::testCamera(w, h, 70, 1.3, -10), RoomBox{}, 0.6);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.6, -2), Vec3(0.4, 0, 0), Vec3(0, 0, 0.4), Vec3::Constant(5)));
  InsertedObject o;
  o.meshObject = test::sphereMesh(0.4, 12, 24);
  o.worldFromObject = test::translation(Vec3(0.3, 0.4, -2.5));
  s.objects.push_back(o);
  return s;
}

TEST(Session, FramesFollowTheScheduleAndMatchTheTracer) {
  const int w = 48, h = 36;
  Collector sink;
  SessionOptions opt;
  opt.targetSpp = 8;
  opt.seed = 17;
  const RenderScene scene = sessionScene(w, h);
  {
    RenderSession session(&sink, opt);
    EXPECT_TRUE(session.waitUntilDone(0.01));  // no scene yet: nothing to do
    const uint64_t v = session.setScene(scene);
    EXPECT_EQ(session.version(), v);
    ASSERT_TRUE(session.waitUntilDone(60));
    EXPECT_FALSE(session.busy());
    const auto frames = sink.frames();
    std::vector<std::pair<int, int>> got;  // (divider, spp)
    for (const auto& e : frames) {
      got.emplace_back(e.frame->resolutionDivider, e.frame->spp);
      EXPECT_EQ(e.frame->sceneVersion, v);
      EXPECT_EQ(e.frame->width, w);
      EXPECT_EQ(e.frame->withObjects.width, w);
      EXPECT_EQ(e.frame->withObjects.height, h);
      EXPECT_EQ(e.frame->mask.channels, 1);
      EXPECT_TRUE(std::isfinite(e.frame->estimatedError));
      EXPECT_EQ(e.frame->final, &e == &frames.back());
    }
    const std::vector<std::pair<int, int>> expected = {{8, 0}, {4, 0}, {2, 0}, {1, 1},
                                                       {1, 2}, {1, 4}, {1, 8}};
    EXPECT_EQ(got, expected);
    // The final frame is the tracer's 8-sample render (same seed), up to float summation order.
    PathTracer tracer(scene, opt.tracer);
    DifferentialBuffers b(w, h);
    ASSERT_TRUE(tracer.render(b, 0, 8, opt.seed));
    const ImageF ref = b.meanWith();
    const ImageF& fin = frames.back().frame->withObjects;
    for (size_t i = 0; i < ref.data.size(); ++i)
      ASSERT_NEAR(fin.data[i], ref.data[i], 1e-4 * (1 + std::abs(ref.data[i])));
    // Preview frames are nearest-upsampled: constant over each 8x8 cell.
    const ImageF& p8 = frames.front().frame->withObjects;
    EXPECT_EQ(p8.at(0, 0, 0), p8.at(7, 7, 0));
    EXPECT_EQ(p8.at(8, 0, 0), p8.at(15, 7, 0));
    // Error estimates fall with samples (4x the samples: about half the error).
    const double e1 = frames[3].frame->estimatedError, e8 = frames.back().frame->estimatedError;
    std::printf("[ session ] estimated sRGB RMSE where with != without: 1 spp %.4f, 8 spp %.4f\n", e1,
                e8);
    EXPECT_GT(e1, 0.0);
    EXPECT_LT(e8, e1);
  }
}

// Edits applied by the render thread at a safe point: after a scene and two quick moves, the
// final frame is the tracer's render of the object at its last position.
TEST(Session, MovesEndAtTheLastTransform) {
  const int w = 48, h = 36;
  Collector sink;
  SessionOptions opt;
  opt.targetSpp = 8;
  opt.seed = 5;
  RenderScene scene = sessionScene(w, h);
  RenderSession session(&sink, opt);
  session.setScene(scene);
  session.setObjectTransform(0, test::translation(Vec3(-0.6, 0.4, -2.2)));
  const Mat4 last = test::translation(Vec3(0.5, 0.5, -2.8));
  const uint64_t v = session.setObjectTransform(0, last);
  ASSERT_TRUE(session.waitUntilDone(60));
  const auto frames = sink.frames();
  ASSERT_FALSE(frames.empty());
  const RenderFrame& fin = *frames.back().frame;
  EXPECT_EQ(fin.sceneVersion, v);
  EXPECT_TRUE(fin.final);
  scene.objects[0].worldFromObject = last;
  PathTracer tracer(scene, opt.tracer);
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 8, opt.seed));
  const ImageF ref = b.meanWith();
  for (size_t i = 0; i < ref.data.size(); ++i)
    ASSERT_NEAR(fin.withObjects.data[i], ref.data[i], 1e-4 * (1 + std::abs(ref.data[i])));
}

// Focused sampling: pixels an object has not touched take part in every 4th wave only. Pixels
// the object covers render exactly as without focus (same samples); quiet ones get fewer.
TEST(Session, FocusOnChangesKeepsTheObjectPixelsAndSavesTime) {
  const int w = 96, h = 72;
  RenderScene scene = sessionScene(w, h);
  scene.objects[0].worldFromObject = test::translation(Vec3(0.8, 0.15, -3.0));
  Mat4 small = scene.objects[0].worldFromObject;
  small.topLeftCorner<3, 3>() *= 0.4;
  scene.objects[0].worldFromObject = small;
  std::shared_ptr<const RenderFrame> last[2];
  double seconds[2];
  for (int focus = 0; focus < 2; ++focus) {
    Collector sink;
    SessionOptions opt;
    opt.targetSpp = 32;
    opt.startDivider = 1;
    opt.focusOnChanges = focus == 1;
    RenderSession session(&sink, opt);
    session.setScene(scene);
    ASSERT_TRUE(session.waitUntilDone(120));
    const auto frames = sink.frames();
    ASSERT_FALSE(frames.empty());
    last[focus] = frames.back().frame;
    seconds[focus] = last[focus]->seconds;
    EXPECT_TRUE(last[focus]->final);
    EXPECT_EQ(last[focus]->spp, 32);
  }
  int objectPx = 0, samePx = 0, differentPx = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool same = last[0]->withObjects.rgb(x, y) == last[1]->withObjects.rgb(x, y) &&
                        last[0]->withoutObjects.rgb(x, y) == last[1]->withoutObjects.rgb(x, y);
      if (last[0]->mask.at(x, y) == 1.f) {
        ++objectPx;
        EXPECT_TRUE(same);
      }
      (same ? samePx : differentPx)++;
    }
  std::printf(
      "[ session ] focus on changes, %dx%d, 32 spp: %.2f s vs %.2f s uniform; %d object px identical, "
      "%d px with fewer samples\n",
      w, h, seconds[1], seconds[0], objectPx, differentPx);
  EXPECT_GT(objectPx, 5);
  EXPECT_GT(differentPx, w * h / 2);
  EXPECT_LT(seconds[1], seconds[0]);  // about 2.5x faster here (most pixels never meet the object)
}

// Adaptive sampling to a noise target: the samples go to the object (and what it changes),
// every changed pixel ends at or below the target, the per-pixel estimate is honest against a
// converged reference, and wherever a uniform render shows no change (no path met the object)
// the adaptive one shows none either, bit for bit: with and without share their samples.
TEST(Session, AdaptiveSamplingMeetsTheNoiseTargetWhereTheObjectChangesThePhoto) {
  const int w = 64, h = 48;
  RenderScene scene = sessionScene(w, h);
  Mat4 small = test::translation(Vec3(0.8, 0.15, -3.0));  // a small object: most of the room untouched
  small.topLeftCorner<3, 3>() *= 0.7;
  scene.objects[0].worldFromObject = small;
  Collector sink;
  SessionOptions opt;
  opt.targetSpp = 1 << 14;
  opt.startDivider = 1;
  opt.noiseTarget = 0.02;
  opt.seed = 3;
  RenderSession session(&sink, opt);
  session.setScene(scene);
  ASSERT_TRUE(session.waitUntilDone(300));
  const auto frames = sink.frames();
  ASSERT_FALSE(frames.empty());
  const RenderFrame& f = *frames.back().frame;
  ASSERT_TRUE(f.final);
  EXPECT_TRUE(f.converged);
  ASSERT_EQ(f.samples.width, w);
  ASSERT_EQ(f.noise.width, w);
  // A uniform reference with many samples (another seed), and a uniform render with the
  // session's seed: where none of its samples meets the object, the adaptive render's (its
  // first samples) cannot either.
  PathTracer tracer(scene, opt.tracer);
  DifferentialBuffers ref(w, h), quiet(w, h);
  ASSERT_TRUE(tracer.render(ref, 0, 512, 99));
  ASSERT_TRUE(tracer.render(quiet, 0, 64, opt.seed));
  const ImageF rw = ref.meanWith(), rwo = ref.meanWithout(), rm = ref.meanMask();
  const ImageF photo(w, h, 3);  // the composite's photo: black (the change is what is tested)
  const ImageF compRef = differentialComposite(photo, rw, rwo, rm);
  const ImageF comp = differentialComposite(photo, f.withObjects, f.withoutObjects, f.mask);
  auto srgb = [](double v) {
    return v <= 0.0031308 ? 12.92 * std::max(0.0, v)
                          : 1.055 * std::pow(std::min(v, 1.0), 1 / 2.4) - 0.055;
  };
  double objSamples = 0, quietSamples = 0, errSq = 0, estSq = 0;
  int objPx = 0, quietPx = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const bool untouched = quiet.sumWith.rgb(x, y) == quiet.sumWithout.rgb(x, y) &&
                             quiet.sumMask.at(x, y) == 0;
      if (untouched && f.samples.data[i] <= 64) {
        ASSERT_EQ(f.withObjects.rgb(x, y), f.withoutObjects.rgb(x, y)) << x << "," << y;
        quietSamples += f.samples.data[i];
        ++quietPx;
      }
      EXPECT_LE(f.noise.data[i], opt.noiseTarget * (1 + 1e-6)) << x << "," << y;
      if (rm.at(x, y) == 1.f && f.mask.at(x, y) == 1.f) {
        objSamples += f.samples.data[i];
        ++objPx;
        for (int c = 0; c < 3; ++c)
          errSq += std::pow(srgb(comp.at(x, y, c)) - srgb(compRef.at(x, y, c)), 2) / 3;
        estSq += double(f.noise.data[i]) * f.noise.data[i];
      }
    }
  ASSERT_GT(objPx, 10);
  ASSERT_GT(quietPx, 20);
  const double rmse = std::sqrt(errSq / objPx), est = std::sqrt(estSq / objPx);
  std::printf(
      "[ session ] adaptive, target %.3f: object %.0f spp (%d px), untouched %.1f spp (%d px), "
      "%.2f s; object RMSE vs 512 spp %.4f, estimated %.4f\n",
      opt.noiseTarget, objSamples / objPx, objPx, quietSamples / quietPx, quietPx, f.seconds, rmse, est);
  EXPECT_GT(objSamples / objPx, 4 * quietSamples / quietPx);
  // The estimate is honest: the true error (its reference's own noise included) within 2x.
  EXPECT_LT(rmse, 2 * est + 0.005);
  EXPECT_GT(rmse, 0.5 * est);
}

TEST(Session, EditCancelsTheRunningWaveQuickly) {
  const int w = 160, h = 120;
  Collector sink;
  SessionOptions opt;
  opt.targetSpp = 1 << 20;
  RenderSession session(&sink, opt);
  const uint64_t v1 = session.setScene(sessionScene(w, h));
  // Wait until long waves run (a full-resolution frame with 4 spp or more is out).
  ASSERT_TRUE(sink.waitFor([&](const auto& f) { return !f.empty() && f.back().frame->spp >= 4; }, 60));
  std::vector<double> latenciesMs;
  uint64_t v = v1;
  for (int k = 0; k < 5; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(60));  // land mid-wave
    const auto t0 = Clock::now();
    v = session.setObjectTransform(0, test::translation(Vec3(-0.5 + 0.2 * k, 0.4, -2.5)));
    ASSERT_TRUE(sink.waitFor(
        [&](const auto& f) { return !f.empty() && f.back().frame->sceneVersion == v; }, 10));
    for (const auto& e : sink.frames())
      if (e.frame->sceneVersion == v) {
        latenciesMs.push_back(std::chrono::duration<double, std::milli>(e.at - t0).count());
        break;
      }
  }
  std::sort(latenciesMs.begin(), latenciesMs.end());
  std::printf(
      "[ session ] edit -> first frame of the new version (160x120, 2 threads busy): median %.1f ms, "
      "max %.1f ms\n",
      latenciesMs[latenciesMs.size() / 2], latenciesMs.back());
  EXPECT_LT(latenciesMs[latenciesMs.size() / 2], 500.0);
  // Versions never go backwards.
  uint64_t last = 0;
  for (const auto& e : sink.frames()) {
    EXPECT_GE(e.frame->sceneVersion, last);
    last = e.frame->sceneVersion;
  }
  EXPECT_EQ(last, v);
  EXPECT_TRUE(session.busy());
  const auto t0 = Clock::now();
  session.cancel();
  EXPECT_TRUE(session.waitUntilDone(5));
  std::printf("[ session ] cancel() -> idle: %.1f ms\n",
              std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  EXPECT_FALSE(session.busy());
}

TEST(Session, TimeLimitEndsWithAFinalFrame) {
  Collector sink;
  SessionOptions opt;
  opt.targetSpp = 1 << 20;
  opt.seconds = 0.3;
  RenderSession session(&sink, opt);
  const auto t0 = Clock::now();
  session.setScene(sessionScene(96, 72));
  ASSERT_TRUE(session.waitUntilDone(10));
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  EXPECT_LT(s, 3.0);
  EXPECT_GT(s, 0.25);
  const auto frames = sink.frames();
  ASSERT_FALSE(frames.empty());
  EXPECT_TRUE(frames.back().frame->final);
  // On a slow machine the time may run out before the first full-resolution wave: then the
  // final frame is the last preview.
  EXPECT_TRUE(frames.back().frame->spp > 0 || frames.back().frame->resolutionDivider > 1);
}

// A time limit shorter than the preview still ends with a final frame (the last preview).
TEST(Session, TinyTimeLimitStillEndsWithAFinalFrame) {
  Collector sink;
  SessionOptions opt;
  opt.targetSpp = 1 << 20;
  opt.seconds = 1e-4;
  RenderSession session(&sink, opt);
  session.setScene(sessionScene(96, 72));
  ASSERT_TRUE(session.waitUntilDone(10));
  const auto frames = sink.frames();
  ASSERT_FALSE(frames.empty());
  EXPECT_TRUE(frames.back().frame->final);
  int finals = 0;
  for (const auto& e : frames) finals += e.frame->final ? 1 : 0;
  EXPECT_EQ(finals, 1);
}

TEST(Session, DestructorStopsARunningRender) {
  Collector sink;
  SessionOptions opt;
  opt.targetSpp = 1 << 20;
  auto session = std::make_unique<RenderSession>(&sink, opt);
  session->setScene(sessionScene(160, 120));
  ASSERT_TRUE(sink.waitFor([](const auto& f) { return f.size() >= 4; }, 60));
  const auto t0 = Clock::now();
  session.reset();
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  std::printf("[ session ] destructor while rendering: %.1f ms\n", ms);
  EXPECT_LT(ms, 1000.0);
}

}  // namespace
}  // namespace inlay
