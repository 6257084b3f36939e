#include "draw/draw_facts.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace rollspin::draw {

// The drawing reads the solving side's poses and facts.
using namespace rollspin::motion;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// "× 2" after a per-circuit formula when the path goes round more than once.
std::string timesTurns(double turns) {
  return std::abs(turns - 1.0) < 1e-12 ? std::string() : fmt::format(" × {:g}", turns);
}

// Lines stay under ~42 characters: a 480-pixel thumbnail's ball view holds
// that at a readable size. Every line is there from the first frame to the
// last (no line jumps); running values end on their final value and stay;
// the comparison with the closed form appears when the circuit completes.
// `endShown`: the circuit's end values are printed (at the end, a strobe, a
// still); in a clip before the end they are "…", revealed at the end.
void deltaLines(const DeltaFact& d, const LiveAngles& live, double labNow, bool atEnd, bool endShown, double turns,
                std::vector<FactLine>& out) {
  if (d.onSphere) {
    out.push_back(fmt::format("δ = 2π√(ρ²/R² + cos²θ){}", timesTurns(turns)));
    out.push_back(fmt::format("  = {:.6f} rad (ρ = r sin θ)", d.closedForm));
  } else {
    out.push_back(fmt::format("δ = 2π√(1 + (r/R)²){} = {:.6f} rad", timesTurns(turns), d.closedForm));
  }
  // Relative to the rolling frame (the frame turning with the path).
  out.push_back({fmt::format("turned, in the rolling frame: {:.4f} rad", atEnd ? d.measured : live.rolling), !atEnd});
  out.push_back(endShown ? fmt::format("solver at the end: {:.6f} rad", d.measured)
                         : std::string("solver at the end: …"));
  if (d.wholeCircuits) {
    // The lab angle of U lies in [0, π]: δ's remainder in (−π, π], in size.
    const double k = std::round(d.closedForm / (2.0 * kPi));
    out.push_back({atEnd ? fmt::format("in the lab: {:.4f}°; |δ − {:g}π|", d.labAngle / kDeg, 2.0 * k)
                         : fmt::format("in the lab: {:.4f}°", labNow / kDeg),
                   !atEnd});
    if (atEnd) out.back().text += fmt::format(" = {:.4f}°", d.closedFormMod / kDeg);
  }
}
void marksLines(const SceneFacts& facts, const FrameOrientations& frame, bool strobe, std::vector<FactLine>& out) {
  const MarksFact& m = *facts.marks;
  out.push_back(fmt::format("a mark every β = π/√(1 + (r/R)²) = {:.2f}°", m.beta / kDeg));
  const int passed = strobe ? int(m.s.size()) : facts.marksPassed(frame.current.s);
  out.push_back(fmt::format("of path angle; marks passed: {} of {}", passed, m.s.size()));
  // The latest completed interval, else the turn since mark 0 so far: two
  // lines either way, so that no line jumps when the second mark passes.
  if (passed >= 2) {
    const std::size_t k = std::size_t(passed) - 2;
    out.push_back(fmt::format("turn from mark {} to {}: {:.6f}°", k, k + 1, m.turn[k] / kDeg));
    out.push_back(fmt::format("  = {:.9f}π, axis {:.2f}° from n", m.turn[k] / kPi, m.axisFromNormal[k] / kDeg));
  } else {
    const spin::Su2 v = facts.rollingFrame(frame.current.s, frame.current.q);
    const double since = spin::rotationAngleAxis(v * m.rolling.front().conjugate()).angle;
    out.push_back({fmt::format("turn since mark 0: {:.2f}°", since / kDeg), true});
    out.push_back({fmt::format("  = {:.2f}π", since / kPi), true});
  }
  out.push_back("(in the frame turning with the path)");
}

void turnsLines(const TurnsFact& t, const LiveAngles& live, bool atEnd, bool endShown, std::vector<FactLine>& out) {
  const double lab = atEnd ? t.lab : live.lab, relative = atEnd ? t.lab - t.frame : live.lab - live.frame;
  out.push_back({fmt::format("turns in the lab: {:.{}f}", std::abs(lab) / (2 * kPi), atEnd ? 6 : 2), !atEnd});
  // Whether the ball turns with or against the revolution is the circuit's.
  out.push_back(endShown ? fmt::format("  {} the revolution", t.lab * t.frame < 0.0 ? "against" : "with")
                         : std::string("  …"));
  out.push_back("turns relative to the radius line:");
  out.push_back({fmt::format("  {:.{}f}{}", std::abs(relative) / (2 * kPi), atEnd ? 6 : 2,
                             atEnd && t.paperPenny ? " (the paper says 1)" : ""),
                 !atEnd});
}

// Everything here is of the closed loop U(L): shown when it closes.
void phaseLines(const PhaseSplitFact& p, bool endShown, std::vector<FactLine>& out) {
  auto value = [endShown](const std::string& text) { return endShown ? text : std::string("…"); };
  out.push_back("cyclic spin X of U(L), " + value(fmt::format("{:.2f}°", p.spinFromField / kDeg)) + " from B:");
  out.push_back("dynamic (1/2)∫B·X ds = " + value(fmt::format("{:.6f}", p.dynamic)));
  out.push_back("geometric −(1/2)Ω(X) = " + value(fmt::format("{:.6f}", p.geometric)));
  out.push_back("sum ≡ total phase " + value(fmt::format("{:.6f}", p.total)) + " (mod 2π)");
  out.push_back("  off by " + value(fmt::format("{:.1e} rad", std::abs(p.residual))));
  out.push_back("Berry: (1/2)∫|B| ds = " + value(fmt::format("{:.4f}", p.adiabaticDynamic)));
  out.push_back("−(1/2)Ω(B) = " + value(fmt::format("{:.6f}", p.berryGeometric)) + " (the blue cone)");
  out.push_back(
      fmt::format("|Ω(B)| = 2π(1 − cos {:.1f}°) = {:.6f}", p.coneAngle / kDeg, 2.0 * std::abs(p.berryClosedForm)));
}

}  // namespace

std::vector<FactLine> factLines(const SceneFacts& facts, const FrameOrientations& frame, double pathLength) {
  std::vector<FactLine> out;
  const bool strobe = !frame.strobe.empty();
  // A strobe shows the whole circuit: its end values.
  const bool atEnd = strobe || frame.current.s >= pathLength * (1.0 - 1e-12);
  // A still has no later frame to reveal them in: they show beside the values at s.
  const bool endShown = atEnd || frame.still;
  const LiveAngles live = facts.at(frame.current.s, frame.current.q);
  const double labNow = spin::rotationAngleAxis(frame.current.q).angle;
  for (const scene::Fact f : facts.facts()) {
    switch (f) {
      case scene::Fact::Delta: deltaLines(*facts.delta, live, labNow, atEnd, endShown, facts.pathTurns(), out); break;
      case scene::Fact::Marks: marksLines(facts, frame, strobe, out); break;
      case scene::Fact::Turns: turnsLines(*facts.turns, live, atEnd, endShown, out); break;
      case scene::Fact::PhaseSplit: phaseLines(*facts.phaseSplit, endShown, out); break;
    }
  }
  return out;
}

std::shared_ptr<render::MeshData> coneMesh(const std::vector<geometry::Vec3>& loop) {
  auto mesh = std::make_shared<render::MeshData>();
  render::Vertex apex;  // the origin; normals are left to the unlit material
  mesh->vertices.push_back(apex);
  for (const auto& p : loop) {
    render::Vertex v;
    v.position = glm::vec3(float(p.x()), float(p.y()), float(p.z()));
    v.normal = glm::normalize(v.position);
    mesh->vertices.push_back(v);
  }
  for (std::uint32_t i = 1; i + 1 < mesh->vertices.size(); ++i)
    mesh->indices.insert(mesh->indices.end(), {0, i, i + 1});
  return mesh;
}

}  // namespace rollspin::draw
