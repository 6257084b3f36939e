// The web viewer's timeline (jobs/viewer_timeline.hpp): knots on every join,
// and dense enough that cubic Hermite with the solver's derivatives
// (dq/ds = −½ (0, B) ⊗ q) meets the solver between knots to 1e-7, where
// Hermite errs most (mid-interval); the clip's clock and the chapters'
// surfaces; base64 against RFC 4648's vectors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "jobs/timeline_csv.hpp"
#include "jobs/viewer_job.hpp"
#include "jobs/viewer_timeline.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/solve_job.hpp"
#include "spin/su2.hpp"
#include "support/test_files.hpp"

using namespace rollspin;

namespace {

using Quat = std::array<double, 4>;

// −½ (0, b) ⊗ q: the spinor's rate, written here from the convention
// (docs/conventions.md), apart from the page's JavaScript.
Quat rate(const Quat& q, const std::array<double, 3>& b) {
  const spin::Su2 field{0.0, b[0], b[1], b[2]}, p{q[0], q[1], q[2], q[3]};
  const spin::Su2 d = field * p;
  return {-0.5 * d.w, -0.5 * d.x, -0.5 * d.y, -0.5 * d.z};
}

Quat hermite(const jobs::ViewerKnot& a, const jobs::ViewerKnot& b, double s) {
  const double h = b.s - a.s, t = (s - a.s) / h, t2 = t * t, t3 = t2 * t;
  const Quat ma = rate(a.q, a.b), mb = rate(b.q, b.b);
  Quat q{};
  for (int i = 0; i < 4; ++i)
    q[i] = (2 * t3 - 3 * t2 + 1) * a.q[i] + (t3 - 2 * t2 + t) * h * ma[i] + (-2 * t3 + 3 * t2) * b.q[i] +
           (t3 - t2) * h * mb[i];
  return q;
}

// The largest |q_Hermite − q_solver| (any component) at the middles of the knot intervals.
double largestMidpointError(const std::string& name) {
  const scene::SceneSpec spec = model::loadScene(test::shippedScenePath(name), {});
  const model::RollingModel model = model::buildSceneModel(spec);
  const motion::SolverChoice choice = motion::chooseSolver(spec, model);
  const jobs::ViewerTimeline timeline = jobs::sampleViewerTimeline(spec, model, choice);
  std::vector<double> middles;
  for (std::size_t k = 0; k + 1 < timeline.knots.size(); ++k)
    middles.push_back(0.5 * (timeline.knots[k].s + timeline.knots[k + 1].s));
  double worst = 0.0;
  jobs::sampleTimeline(
      model, choice, spin::SampleArcLengths(middles),
      [&](std::size_t k, const jobs::TimelineRow& row) {
        const Quat q = hermite(timeline.knots[k], timeline.knots[k + 1], middles[k]);
        for (int i = 0; i < 4; ++i) worst = std::max(worst, std::abs(q[i] - row.values[10 + i]));
      },
      name);
  return worst;
}

TEST(ViewerTimeline, HermiteWithTheSolversRateMeetsTheSolverBetweenKnots) {
  // A constant field, a circle, a storyboard's joins, a clothoid, curved surfaces, a plate.
  for (const char* name : {"wall", "lollipop", "storyboard", "cornu", "torus", "sphere-loxodrome", "height-bumps",
                           "tennis-ball", "cylinder-helix"}) {
    const double error = largestMidpointError(name);
    EXPECT_LT(error, 1e-7) << name;
    std::printf("%-18s largest mid-knot error %.2e\n", name, error);
  }
}

TEST(ViewerTimeline, KnotsLieOnEveryJoinWithATwinJustBefore) {
  const scene::SceneSpec spec = model::loadScene(test::shippedScenePath("storyboard"), {});
  const model::RollingModel model = model::buildSceneModel(spec);
  const std::vector<double> knots = jobs::viewerKnotArcLengths(model);
  ASSERT_TRUE(std::is_sorted(knots.begin(), knots.end()));
  EXPECT_EQ(knots.front(), 0.0);
  EXPECT_EQ(knots.back(), model.path->length());
  ASSERT_GE(model.segments.size(), 2u);
  for (std::size_t k = 1; k < model.segments.size(); ++k) {
    const double join = model.segments[k].start;
    if (!(join > 0.0 && join < model.path->length())) continue;
    const auto at = std::lower_bound(knots.begin(), knots.end(), join);
    ASSERT_NE(at, knots.end());
    EXPECT_EQ(*at, join) << "segment " << k + 1;
    EXPECT_LT(join - *(at - 1), 1e-9 * model.path->length()) << "the twin before segment " << k + 1;
  }
}

TEST(ViewerTimeline, ChaptersAreTheStoryboardsSegmentsWithTheirCaptions) {
  const scene::SceneSpec spec = model::loadScene(test::shippedScenePath("storyboard"), {});
  const model::RollingModel model = model::buildSceneModel(spec);
  const jobs::ViewerTimeline timeline = jobs::sampleViewerTimeline(spec, model, motion::chooseSolver(spec, model));
  ASSERT_EQ(timeline.chapters.size(), spec.segments.size());
  for (std::size_t k = 0; k < spec.segments.size(); ++k) {
    EXPECT_EQ(timeline.chapters[k].number, k + 1);
    EXPECT_EQ(timeline.chapters[k].caption, spec.segments[k].caption);
    EXPECT_EQ(timeline.chapters[k].start, model.segments[k].start);
  }
  const std::string json = jobs::viewerTimelineJson(timeline);
  EXPECT_EQ(json.find('<'), std::string::npos) << "the JSON must not be able to close its <script>";
}

// The page's clock, evaluated here as web/src/clip_clock.js does.
double clockAt(const jobs::ViewerClock& clock, double t) {
  std::size_t k = 0;
  while (k + 1 < clock.s0.size() && clock.seconds[k + 1] <= t) ++k;
  if (!(clock.s1[k] > clock.s0[k])) return clock.s0[k];
  const double x = std::clamp((t - clock.seconds[k]) / (clock.seconds[k + 1] - clock.seconds[k]), 0.0, 1.0);
  return clock.s0[k] + (clock.s1[k] - clock.s0[k]) * (clock.smooth ? x * x * (3.0 - 2.0 * x) : x);
}

// At every frame (and half way between) the clock's pieces show the MP4's
// arc length; on two surfaces the chapters name theirs, and the hold on the
// torus before the floor sits a hair before the join (so s names the torus).
TEST(ViewerTimeline, TheClockIsTheClipsAndChaptersNameTheirSurface) {
  for (const char* name : {"storyboard", "torus-to-floor", "lollipop"}) {
    const scene::SceneSpec spec = model::loadScene(test::shippedScenePath(name), {});
    const model::RollingModel model = model::buildSceneModel(spec);
    const jobs::ViewerTimeline timeline = jobs::sampleViewerTimeline(spec, model, motion::chooseSolver(spec, model));
    const motion::FrameClock clock = motion::clipClock(spec, model);
    const double fps = clock.fps().value(), length = model.path->length();
    ASSERT_NEAR(timeline.clock.seconds.back(), double(clock.frameCount() - 1) / fps, 1e-12) << name;
    for (double f = 0.0; f <= double(clock.frameCount() - 1); f += 0.5)
      EXPECT_NEAR(clockAt(timeline.clock, f / fps), clock.arcLengthAt(f), 2e-10 * length) << name << " frame " << f;
  }
  const scene::SceneSpec spec = model::loadScene(test::shippedScenePath("torus-to-floor"), {});
  const model::RollingModel model = model::buildSceneModel(spec);
  const jobs::ViewerTimeline timeline = jobs::sampleViewerTimeline(spec, model, motion::chooseSolver(spec, model));
  ASSERT_EQ(timeline.chapters.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(timeline.chapters[k].surface, k < 2 ? 0u : 1u) << "chapter " << k + 1;
  const double join = model.segments[2].start;
  // The pieces: the opening hold, round the torus, the hold, the floor's two motions, the closing hold.
  const jobs::ViewerClock& pieces = timeline.clock;
  ASSERT_GE(pieces.s0.size(), 3u);
  EXPECT_EQ(pieces.s0[2], pieces.s1[2]) << "the hold after the torus";
  EXPECT_LT(pieces.s0[2], join);
  EXPECT_GT(pieces.s0[2], join - 1e-9 * model.path->length());
  EXPECT_EQ(pieces.s0[3], join) << "the floor's motion starts at the join itself";
}

TEST(Base64, MatchesRfc4648) {
  const std::vector<std::pair<std::string, std::string>> vectors{{"", ""},
                                                                 {"f", "Zg=="},
                                                                 {"fo", "Zm8="},
                                                                 {"foo", "Zm9v"},
                                                                 {"foob", "Zm9vYg=="},
                                                                 {"fooba", "Zm9vYmE="},
                                                                 {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, encoded] : vectors) EXPECT_EQ(jobs::base64(plain), encoded) << plain;
}

}  // namespace
