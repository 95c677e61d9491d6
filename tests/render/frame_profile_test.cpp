// Where a frame's time goes (render/frame_profile.h, gl/gpu_pass_timers.h): the 95th percentile
// by nearest rank, spans of one pass in a frame adding up, passes that did not run counting as
// no sample; and the pass timers handing back every frame, its passes in order, once the frames
// in flight are collected.
#include <gtest/gtest.h>

#include "gl/gpu_pass_timers.h"
#include "render/frame_profile.h"
#include "test_scenes.h"

namespace bounce::test {
namespace {

TEST(FrameProfile, Percentile95IsTheNearestRank) {
  std::vector<double> hundred, twenty;
  for (int i = 100; i >= 1; --i) hundred.push_back(i);  // order does not matter
  for (int i = 1; i <= 20; ++i) twenty.push_back(i);
  EXPECT_EQ(percentile95(hundred), 95.0);               // rank ceil(95) = 95
  EXPECT_EQ(percentile95(twenty), 19.0);                // rank ceil(19) = 19
  EXPECT_EQ(percentile95({1, 2, 3, 4, 5, 6, 7}), 7.0);  // rank ceil(6.65) = 7
  EXPECT_EQ(percentile95({7.0}), 7.0);
  EXPECT_EQ(percentile95({}), 0.0);
}

TEST(FrameProfile, SpansOfAPassAddUpAndAbsentPassesAreNoSample) {
  FrameProfile profile;
  profile.addGpuFrame({{"shadow", 1.0}, {"lit", 4.0}, {"shadow", 2.0}});
  profile.addGpuFrame({{"lit", 6.0}});
  const std::vector<TimeSummary> passes = profile.gpuPasses();
  ASSERT_EQ(passes.size(), 2u);
  EXPECT_EQ(passes[0].name, "shadow");  // first seen first
  EXPECT_EQ(passes[0].frames, 1u);
  EXPECT_DOUBLE_EQ(passes[0].mean, 3.0);
  EXPECT_EQ(passes[1].name, "lit");
  EXPECT_EQ(passes[1].frames, 2u);
  EXPECT_DOUBLE_EQ(passes[1].mean, 5.0);
  EXPECT_DOUBLE_EQ(*profile.lastGpuFrame(), 6.0);
  profile.addCpu("frame", 2.0);
  profile.addCpu("frame", 4.0);
  ASSERT_EQ(profile.cpu().size(), 1u);
  EXPECT_DOUBLE_EQ(profile.cpu()[0].mean, 3.0);
  EXPECT_DOUBLE_EQ(profile.cpu()[0].p95, 4.0);
}

TEST(GpuPassTimers, EveryFrameComesBackWithItsPassesInOrder) {
  testContext();
  gl::GpuPassTimers timers;
  std::size_t collected = 0;
  for (int frame = 0; frame < 6; ++frame) {
    timers.beginFrame();
    timers.begin("first");
    timers.begin("nested");  // timestamps nest
    timers.end();
    timers.end();
    timers.begin("second");
    timers.end();
    // Never more than kFramesInFlight frames (the current one included) wait to be read.
    collected += timers.takeFinished().size();
    EXPECT_GE(collected + gl::GpuPassTimers::kFramesInFlight, static_cast<std::size_t>(frame + 1));
  }
  timers.finish();
  const std::vector<gl::GpuFrameTimes> rest = timers.takeFinished();
  EXPECT_EQ(collected + rest.size(), 6u);
  for (const gl::GpuFrameTimes& frame : rest) {
    ASSERT_EQ(frame.passes.size(), 3u);
    EXPECT_STREQ(frame.passes[0].name, "first");
    EXPECT_STREQ(frame.passes[1].name, "nested");
    EXPECT_STREQ(frame.passes[2].name, "second");
    for (const gl::GpuFrameTimes::Pass& pass : frame.passes) EXPECT_GE(pass.milliseconds, 0.0);
  }
}

}  // namespace
}  // namespace bounce::test
