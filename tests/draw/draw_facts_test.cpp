// draw/draw_facts: the fact lines each fact prints (closed forms, running values, "…" until the end) and B̂'s cone.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "draw/draw_facts.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/scene_facts.hpp"
#include "support/numbers.hpp"
#include "support/test_files.hpp"

namespace rollspin::draw {
namespace {

using test::kDeg;
using test::kPi;

// A shipped scene (scenes/<name>.toml) with its model and the facts asked
// for. Built in place: SceneFacts keeps a reference to the model.
struct FactScene {
  FactScene(const std::string& name, std::vector<scene::Fact> shown, const std::vector<std::string>& overrides)
      : spec(model::loadScene((test::sourceDir() / "scenes" / (name + ".toml")).string(), overrides)),
        model(model::buildSceneModel(spec)),
        facts(spec, model, std::move(shown)),
        length(model.path->length()) {}
  scene::SceneSpec spec;
  RollingModel model;
  SceneFacts facts;
  double length;
};

std::unique_ptr<const FactScene> loadFactScene(const std::string& name, std::vector<scene::Fact> shown,
                                               const std::vector<std::string>& overrides = {}) {
  return std::make_unique<const FactScene>(name, std::move(shown), overrides);
}

std::vector<FactLine> linesAt(const FactScene& f, double s, bool still = false, bool strobe = false) {
  FrameOrientations frame = motion::solveFrame(f.spec, f.model, s);
  frame.still = still;
  if (strobe) frame.strobe = {frame.current};
  return factLines(f.facts, frame, f.length);
}

// The number printed right after `prefix` in `text` (NaN when the prefix is not there).
double numberAfter(const std::string& text, const std::string& prefix) {
  const std::size_t at = text.find(prefix);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(text.c_str() + at + prefix.size(), nullptr);
}

std::string factTexts(const std::vector<FactLine>& lines) {
  std::string out;
  for (const FactLine& l : lines) out += (l.live ? "  [live] " : "  ") + l.text + "\n";
  return out;
}

bool anyLive(const std::vector<FactLine>& lines) {
  for (const FactLine& l : lines)
    if (l.live) return true;
  return false;
}

// The lollipop (R = 1, r = 3): δ = 2π√(1 + (r/R)²) = 2π√10 per circuit, and
// after whole circuits the lab angle is δ's distance to the nearest even
// multiple of π, here |δ − 6π| (one circuit) or |2δ − 12π| (two).
TEST(FactLines, DeltaPrintsTheClosedFormOfTheScenesRadiiAndTheSolverBesideIt) {
  for (const int turns : {1, 2}) {
    const auto loaded = loadFactScene("lollipop", {scene::Fact::Delta}, {"path.turns=" + std::to_string(turns)});
    const FactScene& f = *loaded;
    const double delta = turns * 2 * kPi * std::sqrt(10.0);
    const double evenPi = 2 * std::round(delta / (2 * kPi));
    const std::vector<FactLine> end = linesAt(f, f.length);
    ASSERT_EQ(end.size(), 4u) << factTexts(end);
    EXPECT_EQ(end[0].text, fmt::format("δ = 2π√(1 + (r/R)²){} = {:.6f} rad", turns == 1 ? "" : " × 2", delta));
    EXPECT_NEAR(numberAfter(end[1].text, "turned, in the rolling frame: "), delta, 1e-4) << end[1].text;
    EXPECT_NEAR(numberAfter(end[2].text, "solver at the end: "), delta, 1e-6) << end[2].text;
    const std::string labPrefix = fmt::format("; |δ − {:g}π| = ", evenPi);
    EXPECT_NEAR(numberAfter(end[3].text, labPrefix), std::abs(delta - evenPi * kPi) / kDeg, 1e-4) << end[3].text;
    EXPECT_NEAR(numberAfter(end[3].text, "in the lab: "), std::abs(delta - evenPi * kPi) / kDeg, 1e-4) << end[3].text;
    EXPECT_FALSE(anyLive(end)) << "the last frame's values are final\n" << factTexts(end);
  }
}

// Mid-clip, the circuit's values wait ("…"); a still has no later frame and
// prints them beside the running values; a strobe shows the circuit only,
// its lines those of the clip's last frame. The same lines every time.
TEST(FactLines, AClipWaitsForTheCircuitsValuesThatAStillOrAStrobeShows) {
  const auto loaded = loadFactScene("lollipop", {scene::Fact::Delta});
  const FactScene& f = *loaded;
  const double s = 0.4 * f.length;
  const std::vector<FactLine> clip = linesAt(f, s), still = linesAt(f, s, true), strobe = linesAt(f, s, false, true);
  const std::vector<FactLine> last = linesAt(f, f.length);
  ASSERT_EQ(clip.size(), 4u) << factTexts(clip);
  ASSERT_EQ(still.size(), clip.size()) << factTexts(still);
  ASSERT_EQ(strobe.size(), clip.size()) << factTexts(strobe);
  EXPECT_EQ(clip[2].text, "solver at the end: …");
  EXPECT_EQ(clip[3].text.find("|δ"), std::string::npos) << clip[3].text;
  EXPECT_TRUE(clip[1].live && clip[3].live) << factTexts(clip);
  EXPECT_FALSE(clip[0].live || clip[2].live) << factTexts(clip);
  // The still: the end value in the waiting line, the running ones as in the clip.
  EXPECT_NEAR(numberAfter(still[2].text, "solver at the end: "), 2 * kPi * std::sqrt(10.0), 1e-6) << still[2].text;
  for (const std::size_t k : {0u, 1u, 3u}) {
    EXPECT_EQ(still[k].text, clip[k].text) << k;
    EXPECT_EQ(still[k].live, clip[k].live) << k;
  }
  for (std::size_t k = 0; k < last.size(); ++k) {
    EXPECT_EQ(strobe[k].text, last[k].text) << k;
    EXPECT_FALSE(strobe[k].live) << k;
  }
}

// Between two frames of a clip only the lines marked live change: a
// retained layer may keep the others.
TEST(FactLines, OnlyTheLiveLinesChangeBetweenFramesOfAClip) {
  const std::pair<const char*, scene::Fact> scenes[] = {
      {"lollipop", scene::Fact::Delta}, {"penny", scene::Fact::Turns}, {"berry", scene::Fact::PhaseSplit}};
  for (const auto& [name, fact] : scenes) {
    const auto loaded = loadFactScene(name, {fact});
    const FactScene& f = *loaded;
    const std::vector<FactLine> a = linesAt(f, 0.3 * f.length), b = linesAt(f, 0.6 * f.length);
    ASSERT_EQ(a.size(), b.size()) << name;
    int liveLines = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].live, b[k].live) << name << " line " << k;
      if (a[k].live) {
        ++liveLines;
        EXPECT_NE(a[k].text, b[k].text) << name << ": a live line runs";
      } else {
        EXPECT_EQ(a[k].text, b[k].text) << name << ": a fixed line stays";
      }
    }
    if (fact != scene::Fact::PhaseSplit) {
      EXPECT_GE(liveLines, 1) << name;
    }
  }
}

// The tennis ball (R = 1 on a circle of r = R1/2 = 1): a mark every
// β = π/√(1 + (r/R)²) = π/√2 of path angle, marks at kβ while kβ ≤ 2π
// (three), and between two marks the ball turns by π about an axis 45°
// from n, at a steady rate in the rolling frame (its field is constant
// there): half way to mark 1 it has turned by π/2. Before the second mark
// the turn since mark 0 runs; the same five lines from the first frame to
// the last.
TEST(FactLines, MarksCountThePassedMarksAndPrintTheTurnBetweenTheLatestTwo) {
  const auto loaded = loadFactScene("tennis-ball", {scene::Fact::Marks});
  const FactScene& f = *loaded;
  const double beta = kPi / std::sqrt(2.0), r = 1.0;
  const int marks = int(std::floor(2 * kPi * f.model.path->turns() / beta + 1e-9)) + 1;
  ASSERT_EQ(marks, 3);
  const std::vector<FactLine> start = linesAt(f, 0.0);
  ASSERT_EQ(start.size(), 5u) << factTexts(start);
  EXPECT_EQ(start[0].text, fmt::format("a mark every β = π/√(1 + (r/R)²) = {:.2f}°", beta / kDeg));
  EXPECT_EQ(start[1].text, "of path angle; marks passed: 1 of 3");
  EXPECT_EQ(start[2].text, "turn since mark 0: 0.00°");
  EXPECT_EQ(start[3].text, "  = 0.00π");
  EXPECT_TRUE(start[2].live && start[3].live) << factTexts(start);
  EXPECT_EQ(start[4].text, "(in the frame turning with the path)");
  const std::vector<FactLine> halfWay = linesAt(f, 0.5 * beta * r);
  ASSERT_EQ(halfWay.size(), 5u) << factTexts(halfWay);
  EXPECT_EQ(halfWay[2].text, "turn since mark 0: 90.00°");
  EXPECT_EQ(halfWay[3].text, "  = 0.50π");
  // Just past the third mark (s = 2β r): the turn from mark 1 to mark 2.
  const std::vector<FactLine> third = linesAt(f, 2 * beta * r + 1e-6);
  ASSERT_EQ(third.size(), 5u) << factTexts(third);
  EXPECT_EQ(third[1].text, "of path angle; marks passed: 3 of 3");
  EXPECT_NEAR(numberAfter(third[2].text, "turn from mark 1 to 2: "), 180.0, 1e-5) << third[2].text;
  EXPECT_NEAR(numberAfter(third[3].text, "  = "), 1.0, 1e-7) << third[3].text;
  EXPECT_NEAR(numberAfter(third[3].text, "π, axis "), 45.0, 0.01) << third[3].text;
  EXPECT_EQ(third[4].text, start[4].text);
  EXPECT_FALSE(anyLive(third)) << factTexts(third);
  // A strobe counts every mark from its first position.
  const std::vector<FactLine> strobe = linesAt(f, 0.0, false, true);
  ASSERT_EQ(strobe.size(), 5u) << factTexts(strobe);
  EXPECT_EQ(strobe[1].text, "of path angle; marks passed: 3 of 3");
}

// The penny (inside a sphere of 3R, on the equator) turns twice in the lab,
// against its revolution, and three times against the radius line, which
// the paper counts as one; half way round, half of each (two decimals).
TEST(FactLines, TurnsPrintThePennysTwoLabAndThreeRelativeTurns) {
  const auto loaded = loadFactScene("penny", {scene::Fact::Turns});
  const FactScene& f = *loaded;
  const std::vector<FactLine> end = linesAt(f, f.length);
  ASSERT_EQ(end.size(), 4u) << factTexts(end);
  EXPECT_EQ(end[0].text, "turns in the lab: 2.000000");
  EXPECT_EQ(end[1].text, "  against the revolution");
  EXPECT_EQ(end[2].text, "turns relative to the radius line:");
  EXPECT_EQ(end[3].text, "  3.000000 (the paper says 1)");
  const std::vector<FactLine> half = linesAt(f, 0.5 * f.length);
  ASSERT_EQ(half.size(), 4u) << factTexts(half);
  EXPECT_EQ(half[0].text, "turns in the lab: 1.00");
  EXPECT_EQ(half[1].text, "  …");
  EXPECT_EQ(half[3].text, "  1.50");
  EXPECT_TRUE(half[0].live && half[3].live) << factTexts(half);
}

// Berry's scene (R = 0.25 on a sphere of r = 5, colatitude θ = 50°): the
// field B = −(1/R)(1 + R/r) u has |B| = 4.2 all along the parallel of
// length 2π r sin θ, so (1/2)∫|B| ds = π r sin θ · 4.2; B̂ = −u lies in the
// meridian plane at 90° − θ = 40° from the axis (u ⊥ n, n at θ from it), so
// |Ω(B̂)| = 2π(1 − cos 40°). The loop's values wait for its end in a clip.
TEST(FactLines, PhaseSplitPrintsBerrysConeAndTheAdiabaticDynamicPhase) {
  const auto loaded = loadFactScene("berry", {scene::Fact::PhaseSplit});
  const FactScene& f = *loaded;
  const double theta = 50 * kDeg, alpha = 40 * kDeg;
  const std::vector<FactLine> end = linesAt(f, f.length);
  ASSERT_EQ(end.size(), 8u) << factTexts(end);
  EXPECT_NEAR(numberAfter(end[5].text, "Berry: (1/2)∫|B| ds = "), kPi * 5.0 * std::sin(theta) * 4.2, 1e-4)
      << end[5].text;
  EXPECT_EQ(end[7].text,
            fmt::format("|Ω(B)| = 2π(1 − cos {:.1f}°) = {:.6f}", alpha / kDeg, 2 * kPi * (1 - std::cos(alpha))));
  // Dynamic + geometric is the total phase: the printed residual is tiny.
  EXPECT_LT(std::abs(numberAfter(end[4].text, "  off by ")), 1e-8) << end[4].text;
  const std::vector<FactLine> mid = linesAt(f, 0.5 * f.length);
  ASSERT_EQ(mid.size(), end.size()) << factTexts(mid);
  for (const std::size_t k : {0u, 1u, 2u, 3u, 5u, 6u})
    EXPECT_NE(mid[k].text.find("…"), std::string::npos) << mid[k].text;
  EXPECT_EQ(mid[4].text, "  off by …");
  EXPECT_EQ(mid[7].text, end[7].text) << "the cone's closed form needs no solver";
}

// A loop of n points (closed: the last repeats the first) gives the apex at
// the origin, the n points with their own directions as normals, and the
// n − 1 triangles (0, i, i + 1) between neighbours.
TEST(ConeMesh, FansFromTheOriginThroughEveryPointOfTheLoop) {
  std::vector<geometry::Vec3> loop;
  for (int k = 0; k <= 6; ++k)
    loop.push_back(
        geometry::Vec3(std::sin(0.5) * std::cos(k * kPi / 3), std::sin(0.5) * std::sin(k * kPi / 3), std::cos(0.5)));
  const auto mesh = coneMesh(loop);
  ASSERT_EQ(mesh->vertices.size(), loop.size() + 1);
  EXPECT_EQ(mesh->vertices[0].position, glm::vec3(0.0f));
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const glm::vec3 p = mesh->vertices[i + 1].position;
    EXPECT_FLOAT_EQ(p.x, float(loop[i].x())) << i;
    EXPECT_FLOAT_EQ(p.y, float(loop[i].y())) << i;
    EXPECT_FLOAT_EQ(p.z, float(loop[i].z())) << i;
    EXPECT_NEAR(glm::length(mesh->vertices[i + 1].normal - p), 0.0f, 1e-6f) << i << ": a unit point is its own normal";
  }
  std::vector<std::uint32_t> expected;
  for (std::uint32_t i = 1; i < loop.size(); ++i) expected.insert(expected.end(), {0, i, i + 1});
  EXPECT_EQ(mesh->indices, expected);
  EXPECT_TRUE(coneMesh({})->indices.empty());
}

}  // namespace
}  // namespace rollspin::draw
