// FramePoseStream: the one-march poses of a clip against solveFrame (a full
// march per frame) — current pose, trail and strobe within 1e-12 (they are in
// fact the same numbers: a sample never feeds back into the march) — and a
// partial range against the full clip, on scenes that take different march
// paths: the rigid-field block kernel (lollipop), varying curvatures with
// breakpoints (cornu, plane-spline), the adaptive frame6a, holds and a strobe.
#include <gtest/gtest.h>

#include <cmath>

#include "model/rolling_model.hpp"
#include "motion/frame_poses.hpp"
#include "motion/frame_sampling.hpp"
#include "support/test_files.hpp"

namespace rollspin::motion {
namespace {
using namespace rollspin::model;

double distance(const spin::Su2& a, const spin::Su2& b) {
  return std::max({std::abs(a.w - b.w), std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

void expectSame(const std::vector<OrientedSample>& a, const std::vector<OrientedSample>& b, const char* what,
                long long k) {
  ASSERT_EQ(a.size(), b.size()) << what << " of frame " << k;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].s, b[i].s) << what << " " << i << " of frame " << k;
    EXPECT_LE(distance(a[i].q, b[i].q), 1e-12) << what << " " << i << " of frame " << k;
  }
}

// Pulls every pose of frames range.first … range.last, one per frame index.
std::vector<FrameOrientations> streamed(const scene::SceneSpec& spec, const RollingModel& model,
                                        const FrameClock& clock, FrameRange range) {
  FramePoseStream stream(spec, model, clock, range);
  std::vector<FrameOrientations> out;
  for (long long k = range.first; k <= range.last; ++k) {
    if (k > range.first && clock.arcLength(k) == clock.arcLength(k - 1)) {
      out.push_back(out.back());  // a hold: the stream emits the pose once
      continue;
    }
    std::optional<FrameOrientations> f = stream.next();
    EXPECT_TRUE(f.has_value()) << "frame " << k;
    if (!f) break;
    EXPECT_EQ(f->current.s, clock.arcLength(k)) << "frame " << k;
    out.push_back(std::move(*f));
  }
  EXPECT_FALSE(stream.next().has_value()) << "one pose per distinct arc length, no more";
  return out;
}

void checkScene(const std::string& file, const std::vector<std::string>& overrides) {
  SCOPED_TRACE(file);
  const scene::SceneSpec spec = loadScene((test::sourceDir() / "scenes" / file).string(), overrides);
  const RollingModel model = buildSceneModel(spec);
  const FrameClock clock(model.path->length(), spec);
  const FrameRange all{0, clock.frameCount() - 1};
  const std::vector<FrameOrientations> poses = streamed(spec, model, clock, all);
  ASSERT_EQ(static_cast<long long>(poses.size()), clock.frameCount());
  for (long long k = 0; k < clock.frameCount(); ++k) {
    const FrameOrientations expected = solveFrame(spec, model, clock.arcLength(k));
    const FrameOrientations& got = poses[static_cast<std::size_t>(k)];
    EXPECT_EQ(got.current.s, expected.current.s);
    EXPECT_LE(distance(got.current.q, expected.current.q), 1e-12) << "frame " << k;
    expectSame(got.trail, expected.trail, "trail", k);
    expectSame(got.strobe, expected.strobe, "strobe", k);
  }
  // A part of the clip, starting mid-motion: the same numbers, bit for bit.
  const FrameRange part{clock.frameCount() / 3, clock.frameCount() / 3 + 4};
  const std::vector<FrameOrientations> partial = streamed(spec, model, clock, part);
  ASSERT_EQ(partial.size(), 5u);
  for (long long k = part.first; k <= part.last; ++k) {
    const FrameOrientations& a = partial[static_cast<std::size_t>(k - part.first)];
    const FrameOrientations& b = poses[static_cast<std::size_t>(k)];
    EXPECT_EQ(a.current.q.w, b.current.q.w);
    EXPECT_EQ(a.current.q.x, b.current.q.x);
    EXPECT_EQ(a.current.q.y, b.current.q.y);
    EXPECT_EQ(a.current.q.z, b.current.q.z);
    ASSERT_EQ(a.trail.size(), b.trail.size());
    for (std::size_t i = 0; i < a.trail.size(); ++i) EXPECT_EQ(distance(a.trail[i].q, b.trail[i].q), 0.0);
  }
}

const std::vector<std::string> kShortClip{"animation.duration=1.5", "animation.fps=12", "animation.hold=0.25"};

std::vector<std::string> with(std::vector<std::string> more) {
  more.insert(more.begin(), kShortClip.begin(), kShortClip.end());
  return more;
}

TEST(FramePoseStream, OneMarchGivesThePerFrameSolvesPoses) {
  checkScene("lollipop.toml", with({"path.turns=3"}));
  checkScene("cornu.toml", with({}));
  checkScene("plane-spline.toml", with({"animation.easing=linear"}));
  checkScene("tennis-ball.toml", with({"render.strobe=5"}));
  checkScene("lollipop.toml", with({"solver.tolerance=1e-9", "path.turns=2"}));  // frame6a
  checkScene("lollipop.toml", with({"render.trails=false", "animation.hold=0"}));
}

}  // namespace
}  // namespace rollspin::motion
