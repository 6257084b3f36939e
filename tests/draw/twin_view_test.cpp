// The twin view (draw/twin_view.hpp) checked on its DrawList: the spin's
// arrow is the Bloch vector ⟨ψ|σ|ψ⟩ of ψ(s) = U(s) ψ(0), computed here from
// the spinor's 2×2 matrix (not through the rotation the view uses); the
// field's arrow is B/|B|, on a plane −(n × t)/R's direction with t from the
// path's points; the trails are those vectors at the trail's samples, on the
// unit sphere; and what the scene switches off (labels, trails) is absent.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "draw/draw_style.hpp"
#include "draw/twin_view.hpp"
#include "loaded_scene.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_sampling.hpp"
#include "render/mesh_builders.hpp"
#include "support/test_files.hpp"

namespace rollspin::draw {
namespace twin_view_test {

using geometry::Vec3;
using Complex = std::complex<double>;

using scene_fixture::load;
using scene_fixture::Loaded;

Vec3 toVec(const glm::vec3& p) { return {double(p.x), double(p.y), double(p.z)}; }

// The Bloch vector of U ψ0, ψ0 the spin-up state along the unit vector m:
// U = w − i(x σx + y σy + z σz) as a matrix, ψ0 = (cos θ/2, e^{iφ} sin θ/2)
// for m's polar angles, and ⟨ψ|σ|ψ⟩ = (2 Re a*b, 2 Im a*b, |a|² − |b|²).
Vec3 blochVector(const spin::Su2& q, const Vec3& m) {
  const Complex i(0.0, 1.0);
  const Complex u00 = q.w - i * q.z, u01 = -i * q.x - q.y, u10 = -i * q.x + q.y, u11 = q.w + i * q.z;
  const double theta = std::acos(std::clamp(m.z(), -1.0, 1.0)), phi = std::atan2(m.y(), m.x());
  const Complex a0 = std::cos(0.5 * theta), b0 = std::exp(i * phi) * std::sin(0.5 * theta);
  const Complex a = u00 * a0 + u01 * b0, b = u10 * a0 + u11 * b0;
  const Complex ab = std::conj(a) * b;
  return {2.0 * ab.real(), 2.0 * ab.imag(), std::norm(a) - std::norm(b)};
}

// On a plane (κ_n = τ_g = 0) B = −u/R, u = n × t: its direction from the
// path's tangent by central differences.
Vec3 planeFieldDirection(const model::RollingModel& m, double s) {
  const double h = 1e-5;
  const geometry::DarbouxSample f = m.path->at(s);
  const Vec3 t = (m.path->at(s + h).point - m.path->at(s - h).point).normalized();
  return -f.normal.cross(t).normalized();
}

struct Drawn {
  render::DrawList list;
  motion::FrameOrientations frame;
};

Drawn drawTwin(const Loaded& l, const Vec3& marker, double s) {
  const TwinView twin(l.spec, l.model, nullptr, marker, render::uvSphere(12, 6), FigureText{});
  Drawn d;
  d.list.width = 800;
  d.list.height = 600;
  render::View v;
  v.width = 800;
  v.height = 600;
  d.list.views.push_back(v);
  d.frame = motion::solveFrame(l.spec, l.model, s);
  twin.add(d.list, d.frame, 0, CameraFraming::Aim{Vec3::Zero(), 5.0, 0.7, 0.4, 40.0});
  return d;
}

// The trail of one colour, its growing pieces joined (each starts on the
// previous one's last point).
std::vector<Vec3> trailOf(const render::DrawList& list, const glm::vec4& color) {
  std::vector<Vec3> points;
  for (const render::PolylineItem& p : list.polylines) {
    if (p.color != color || p.points.empty()) continue;
    for (std::size_t k = points.empty() ? 0 : 1; k < p.points.size(); ++k) points.push_back(toVec(p.points[k]));
  }
  return points;
}


TEST(TwinView, SpinArrowIsTheBlochVectorOfTheStateAtS) {
  const Loaded l = load("scenes/sphere-loxodrome.toml");
  const Vec3 marker = Vec3(0.3, -0.5, 0.8).normalized();  // not the default top
  const double length = l.model.path->length();
  for (const double share : {0.0, 0.37, 0.81}) {
    const Drawn d = drawTwin(l, marker, share * length);
    ASSERT_FALSE(d.list.arrows.empty());
    const render::ArrowItem& spinArrow = d.list.arrows.front();
    EXPECT_EQ(spinArrow.color, kMarkerColor);
    EXPECT_EQ(spinArrow.origin, glm::vec3(0.0f));
    const Vec3 expected = blochVector(d.frame.current.q, marker);
    EXPECT_NEAR(expected.norm(), 1.0, 1e-9);
    EXPECT_NEAR((toVec(spinArrow.tip) - expected).norm(), 0.0, 1e-5) << "s = " << share << " L";
  }
  // The state moves: at 0.81 L the arrow is not where it started.
  const Drawn start = drawTwin(l, marker, 0.0), later = drawTwin(l, marker, 0.81 * length);
  EXPECT_GT((toVec(start.list.arrows.front().tip) - toVec(later.list.arrows.front().tip)).norm(), 1e-2);
}

TEST(TwinView, FieldArrowAndTrailsFollowBAndTheBlochVectorOnTheUnitSphere) {
  const Loaded l = load("scenes/lollipop.toml");  // a circle on the floor
  const Vec3 marker = Vec3(1.0, 0.0, 1.0).normalized();
  const double s = 0.6 * l.model.path->length();
  const Drawn d = drawTwin(l, marker, s);
  ASSERT_EQ(d.list.arrows.size(), 2u);  // the spin and the field, no strobe
  const render::ArrowItem& field = d.list.arrows[1];
  EXPECT_EQ(field.color, kFieldColor);
  EXPECT_NEAR((toVec(field.tip) - planeFieldDirection(l.model, s)).norm(), 0.0, 1e-5);

  // The spin's trail: the Bloch vector at each trail sample, ending at s.
  const std::vector<Vec3> bloch = trailOf(d.list, glm::vec4(kBlochTrailColor));
  ASSERT_EQ(bloch.size(), d.frame.trail.size());
  ASSERT_GT(bloch.size(), 20u);
  for (std::size_t i = 0; i < bloch.size(); ++i) {
    EXPECT_NEAR(bloch[i].norm(), 1.0, 1e-5);
    EXPECT_NEAR((bloch[i] - blochVector(d.frame.trail[i].q, marker)).norm(), 0.0, 1e-5) << "point " << i;
  }
  EXPECT_NEAR((bloch.back() - toVec(d.list.arrows[0].tip)).norm(), 0.0, 1e-5);
  // The field's trail: B̂ at each sample.
  const std::vector<Vec3> fieldTrail = trailOf(d.list, glm::vec4(kFieldTrailColor));
  ASSERT_EQ(fieldTrail.size(), d.frame.trail.size());
  for (std::size_t i = 0; i < fieldTrail.size(); ++i) {
    EXPECT_NEAR(fieldTrail[i].norm(), 1.0, 1e-5);
    const double si = std::clamp(d.frame.trail[i].s, 1e-4, l.model.path->length() - 1e-4);
    EXPECT_NEAR((fieldTrail[i] - planeFieldDirection(l.model, si)).norm(), 0.0, 1e-4) << "point " << i;
  }
  // Every trail is on the unit sphere and keeps text off; the labels name
  // the axes and the poles.
  for (const render::PolylineItem& p : d.list.polylines)
    if (p.labelsKeepOff) {
      for (const glm::vec3& q : p.points) EXPECT_NEAR(glm::length(q), 1.0f, 1e-5f);
    }
  std::vector<std::string> texts;
  for (const render::LabelItem& label : d.list.labels) texts.push_back(label.text);
  for (const char* name : {"x", "y", "z", "|0⟩", "|1⟩"})
    EXPECT_NE(std::find(texts.begin(), texts.end(), name), texts.end()) << name;
}

TEST(TwinView, WhatTheSceneSwitchesOffIsAbsentAndAStrobeAddsPalerArrows) {
  const Vec3 marker = Vec3::UnitZ();
  {
    const Loaded l = load("scenes/lollipop.toml", {"render.labels=false", "render.trails=false"});
    const Drawn d = drawTwin(l, marker, 0.5 * l.model.path->length());
    EXPECT_TRUE(d.list.labels.empty());
    for (const render::PolylineItem& p : d.list.polylines)
      EXPECT_FALSE(p.labelsKeepOff && !p.points.empty()) << "a trail with " << p.points.size() << " points";
    EXPECT_EQ(d.list.arrows.size(), 2u);
  }
  {
    const Loaded l = load("scenes/lollipop.toml", {"render.strobe=5"});
    const Drawn d = drawTwin(l, marker, 0.5 * l.model.path->length());
    ASSERT_EQ(d.frame.strobe.size(), 5u);
    ASSERT_EQ(d.list.arrows.size(), 2u + 5u);
    for (std::size_t k = 0; k < 5; ++k) {
      const render::ArrowItem& a = d.list.arrows[2 + k];
      EXPECT_NEAR((toVec(a.tip) - blochVector(d.frame.strobe[k].q, marker)).norm(), 0.0, 1e-5);
      EXPECT_LT(a.shaftRadius, d.list.arrows[0].shaftRadius);
      EXPECT_GT(a.color.r + a.color.g + a.color.b, kMarkerColor.r + kMarkerColor.g + kMarkerColor.b);  // paler
    }
  }
}

}  // namespace twin_view_test
}  // namespace rollspin::draw
