// FrameClock: frame index → arc length, frame counts with holds, easing, and
// the --frames range parser.
#include <gtest/gtest.h>

#include <vector>

#include "core/error.hpp"
#include "motion/frame_clock.hpp"

namespace rollspin::motion {
namespace {
using namespace rollspin::model;

scene::SceneSpec animation(double duration, long long fps, double hold, scene::Easing easing) {
  scene::SceneSpec spec;
  spec.animation.duration = duration;
  spec.animation.fps = {fps, 1};
  spec.animation.hold = hold;
  spec.animation.easing = easing;
  return spec;
}

TEST(FrameClock, CountIsDurationTimesFpsPlusTwoHolds) {
  const FrameClock clock(18.0, animation(10.0, 30, 0.5, scene::Easing::Smooth));
  EXPECT_EQ(clock.motionFrames(), 300);
  EXPECT_EQ(clock.holdFrames(), 15);
  EXPECT_EQ(clock.frameCount(), 330);
}

TEST(FrameClock, HoldsShowTheEndsAndMotionIsMonotonic) {
  const double L = 18.84955592153876;
  for (auto easing : {scene::Easing::Linear, scene::Easing::Smooth}) {
    const FrameClock clock(L, animation(2.0, 30, 0.2, easing));
    ASSERT_EQ(clock.frameCount(), 60 + 12);
    for (long long k = 0; k <= 6; ++k) EXPECT_EQ(clock.arcLength(k), 0.0);
    for (long long k = 65; k < 72; ++k) EXPECT_EQ(clock.arcLength(k), L) << "exactly L, not L(1 − ε)";
    for (long long k = 1; k < clock.frameCount(); ++k) EXPECT_LE(clock.arcLength(k - 1), clock.arcLength(k));
    EXPECT_GT(clock.arcLength(7), 0.0);
    EXPECT_LT(clock.arcLength(64), L);
  }
}

TEST(FrameClock, LinearIsUniformAndSmoothStartsAndStopsAtRest) {
  const FrameClock linear(10.0, animation(1.1, 10, 0.0, scene::Easing::Linear));
  ASSERT_EQ(linear.frameCount(), 11);
  for (long long k = 0; k < 11; ++k) EXPECT_DOUBLE_EQ(linear.arcLength(k), double(k));
  EXPECT_EQ(linear.arcLength(5), 10.0 * 0.5) << "the same product as a still at fraction=0.5";
  const FrameClock smooth(10.0, animation(1.1, 10, 0.0, scene::Easing::Smooth));
  EXPECT_LT(smooth.arcLength(1), 0.5 * linear.arcLength(1));
  EXPECT_NEAR(smooth.arcLength(5), 5.0, 1e-12);
  EXPECT_NEAR(smooth.arcLength(10) - smooth.arcLength(9), smooth.arcLength(1), 1e-12) << "symmetric";
}

TEST(FrameClock, NtscCountsUseTheExactRational) {
  scene::SceneSpec spec = animation(10.0, 30, 0.5, scene::Easing::Linear);
  spec.animation.fps = {30000, 1001};
  const FrameClock clock(5.0, spec);
  EXPECT_EQ(clock.motionFrames(), 300) << "round(10 · 29.97002997) = round(299.7)";
  EXPECT_EQ(clock.holdFrames(), 15) << "round(0.5 · 29.97) = round(14.985)";
  spec.animation.duration = 100.0;
  EXPECT_EQ(FrameClock(5.0, spec).motionFrames(), 2997) << "not 3000: the rate is below 30";
}

TEST(FrameClock, SpeedGivesTheDuration) {
  scene::SceneSpec spec = animation(99.0, 24, 0.0, scene::Easing::Linear);
  spec.animation.speed = 2.0;  // 12 / 2 = 6 s
  EXPECT_EQ(FrameClock(12.0, spec).frameCount(), 144);
}

TEST(FrameClock, TooFewOrTooManyFramesAreBadInput) {
  EXPECT_THROW(FrameClock(1.0, animation(0.01, 30, 0.0, scene::Easing::Linear)), Error);
  EXPECT_THROW(FrameClock(1.0, animation(36000.0, 240, 3600.0, scene::Easing::Linear)), Error);
}

// The continuous clock (a glTF export's key times) is the frame clock at
// whole frames, non-decreasing in between, and flat over holds.
void expectContinuousClockAgrees(const FrameClock& clock) {
  for (long long k = 0; k < clock.frameCount(); ++k)
    EXPECT_DOUBLE_EQ(clock.arcLengthAt(double(k)), clock.arcLength(k)) << k;
  double previous = 0.0;
  for (double f = 0.0; f <= double(clock.frameCount() - 1); f += 0.125) {
    EXPECT_GE(clock.arcLengthAt(f), previous) << f;
    previous = clock.arcLengthAt(f);
  }
  const std::vector<double> bounds = clock.motionBounds();
  EXPECT_EQ(bounds.front(), 0.0);
  EXPECT_EQ(bounds.back(), double(clock.frameCount() - 1));
}

TEST(FrameClock, ContinuousArcLengthMatchesEveryFrame) {
  const FrameClock clock(18.0, animation(2.0, 30, 0.5, scene::Easing::Smooth));
  expectContinuousClockAgrees(clock);
  EXPECT_EQ(clock.motionBounds(), (std::vector<double>{0.0, 15.0, 74.0, 89.0}));
  EXPECT_EQ(clock.arcLengthAt(10.3), 0.0);   // the opening hold
  EXPECT_EQ(clock.arcLengthAt(80.5), 18.0);  // the closing hold
}

TEST(FrameClock, ContinuousArcLengthFollowsAStoryboard) {
  scene::SceneSpec spec = animation(2.0, 10, 0.3, scene::Easing::Smooth);
  spec.segments.resize(3);
  spec.segments[0].path = scene::PathSpec{};
  spec.segments[0].duration = 1.0;
  spec.segments[1].hold = 0.5;  // a hold at s = 2
  spec.segments[2].path = scene::PathSpec{};
  spec.segments[2].duration = 2.0;
  const std::vector<SegmentSpan> spans{{0.0, 2.0}, {2.0, 2.0}, {2.0, 5.0}};
  const FrameClock clock(spans, spec);
  expectContinuousClockAgrees(clock);
  // Opening hold 3 frames, motion 10, hold 5, motion 20, closing hold 3.
  EXPECT_EQ(clock.motionBounds(), (std::vector<double>{0.0, 2.0, 12.0, 17.0, 37.0, 40.0}));
  EXPECT_EQ(clock.arcLengthAt(14.5), 2.0);
  EXPECT_GT(clock.arcLengthAt(17.5), 2.0);
}

TEST(FrameRange, ParsesInclusiveRangesInsideTheClip) {
  const FrameRange r = parseFrameRange("10:19", 100);
  EXPECT_EQ(r.first, 10);
  EXPECT_EQ(r.last, 19);
  EXPECT_EQ(r.count(), 10);
  EXPECT_EQ(parseFrameRange("0:99", 100).count(), 100);
  for (const char* bad : {"", "10", "10:", ":5", "a:b", "5:2", "-1:3", "0:100", "1:2:3", "1.5:3"})
    EXPECT_THROW((void)parseFrameRange(bad, 100), Error) << bad;
}

}  // namespace
}  // namespace rollspin::motion
