// SceneFacts — the numbers a scene's fact labels print ([labels] facts),
// every one measured on the solver's U(s) and set beside its closed form:
//   rolling frame   V(s) = W(s)† U(s), W the continuous spinor of the Darboux
//                   frame's own turn F(s) F(0)ᵀ (U = W V, frame4's split)
//   delta           |Σ log V(sᵢ₊₁)V(sᵢ)†| after the path  vs  2π·turns·√(1 + (r/R)²)
//                   (plane circle) or 2π·turns·√(ρ²/R² + cos²θ), ρ = r sin θ (parallel)
//   marks           s_k = k β r, β = π/√(1 + (r/R)²): the angle of V(s_{k+1}) V(s_k)† (π)
//   turns           Σ log U(sᵢ₊₁)U(sᵢ)† · â (lab) and Σ log W(sᵢ₊₁)W(sᵢ)† · â (the radius
//                   line), â the axis of the revolution; counts = angle / 2π
//   phase-split     the cyclic spin X₀ = ±axis of U(L) nearer B(0): total phase ∓ψ/2 =
//                   dynamic ½∫B·X ds + geometric −½Ω(X) (Aharonov–Anandan, exact), next
//                   to Berry's adiabatic −½Ω(B̂) with Ω(B̂) = 2π·turns·(1 − cos α)
// Logs of increments are unwrapped on a grid fine enough that each step
// turns by far less than π. Numeric only: no GL, no text (draw_scene formats).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "model/rolling_model.hpp"
#include "scene/scene_spec.hpp"
#include "spin/su2.hpp"

namespace rollspin::motion {

using model::RollingModel;
using model::SegmentSpan;

struct DeltaFact {
  double measured = 0.0;       // rad, unwrapped rotation relative to the rolling frame after the path
  double closedForm = 0.0;     // rad
  bool onSphere = false;       // which closed form (the derived one on a sphere, docs/solver.md#notes-on-the-paper)
  double labAngle = 0.0;       // the lab rotation angle of U(L) in [0, π]
  double closedFormMod = 0.0;  // |remainder(closedForm, 2π)|: what labAngle must be after whole circuits
  bool wholeCircuits = true;   // else the frame's own turn is in U(L) too, and labAngle ≠ closedFormMod
};

struct MarksFact {
  double beta = 0.0;                   // path angle per mark (rad): π/√(1 + (r/R)²)
  double circleRadius = 0.0;           // r
  std::vector<double> s;               // arc length of each mark in [0, L]
  std::vector<spin::Su2> rolling;      // V(s_k), the rolling-frame spinor at each mark
  std::vector<double> turn;            // angle of V(s_{k+1}) V(s_k)† (rad), one per interval
  std::vector<double> axisFromNormal;  // angle of that rotation's axis to n(0) (rad), folded into [0, π/2]
};

struct TurnsFact {
  double lab = 0.0;         // signed lab angle about the revolution axis after the path (rad)
  double frame = 0.0;       // the radius line's turn (rad, > 0)
  bool paperPenny = false;  // inside, r = 3R: the paper's penny, which it counts as 1 turn
};

struct PhaseSplitFact {
  double total = 0.0;                     // phase of U(L) on the cyclic spin, in (−π, π]
  double dynamic = 0.0;                   // ½∫ B·X ds
  double geometric = 0.0;                 // −½ Ω(X)
  double residual = 0.0;                  // total − dynamic − geometric, wrapped into (−π, π]
  double spinFromField = 0.0;             // angle between X₀ and B̂(0)
  double adiabaticDynamic = 0.0;          // ½∫|B| ds
  double berryGeometric = 0.0;            // −½ Ω(B̂), quadrature of B̂'s loop
  double coneAngle = 0.0;                 // α, the half-angle of B̂'s cone about the path's turning axis
  double berryClosedForm = 0.0;           // −½ · (±2π·turns·(1 − cos α)), the sign of Ω(B̂)
  std::vector<geometry::Vec3> fieldLoop;  // B̂ along the path (closed), for the twin's cone
};

// Angles at one arc length, unwrapped continuously from s = 0.
struct LiveAngles {
  double rolling = 0.0;  // |Σ log V increments|: rotation relative to the rolling frame (rad)
  double lab = 0.0;      // lab angle about the revolution axis (turns fact; 0 otherwise)
  double frame = 0.0;    // the radius line's turn about that axis
};

class SceneFacts {
 public:
  // Runs the scene's solver (same method and steps as `solve`) on grids of
  // its own. `facts` must apply to the scene (factRule).
  SceneFacts(const scene::SceneSpec& spec, const RollingModel& model, std::vector<scene::Fact> facts);

  [[nodiscard]] const std::vector<scene::Fact>& facts() const { return facts_; }
  [[nodiscard]] bool shows(scene::Fact f) const;
  [[nodiscard]] double pathTurns() const { return model_.path->turns(); }

  std::optional<DeltaFact> delta;
  std::optional<MarksFact> marks;
  std::optional<TurnsFact> turns;
  std::optional<PhaseSplitFact> phaseSplit;

  // Live angles at s, given the solver's U(s) there (exact: the increment
  // from the nearest grid point below s is added, not interpolated).
  [[nodiscard]] LiveAngles at(double s, const spin::Su2& u) const;
  // Marks with s_k ≤ s (≥ 1 when marks are shown).
  [[nodiscard]] int marksPassed(double s) const;
  // The rolling-frame spinor V(s) = W(s)† U(s) (W lifted from the grid).
  [[nodiscard]] spin::Su2 rollingFrame(double s, const spin::Su2& u) const;

 private:
  [[nodiscard]] spin::Su2 frameSpinorNear(double s, const spin::Su2& near) const;
  // The constructor's stages: the unwrapping grid (budget = ∫ step budget
  // over the path), then each fact measured on it.
  void unwrapOnGrid(const scene::SceneSpec& spec, double budget);
  [[nodiscard]] DeltaFact measureDelta(const scene::SceneSpec& spec) const;
  [[nodiscard]] TurnsFact measureTurns(const scene::SceneSpec& spec) const;
  [[nodiscard]] MarksFact measureMarks(const scene::SceneSpec& spec) const;
  [[nodiscard]] PhaseSplitFact measurePhaseSplit(const scene::SceneSpec& spec, double budget) const;

  const RollingModel& model_;
  std::vector<scene::Fact> facts_;
  geometry::Vec3 revolutionAxis_ = geometry::Vec3::UnitZ();
  // The unwrapping grid: s, U, W (lifted), and the running sums of the
  // increments' rotation vectors (lab, frame, rolling frame).
  std::vector<double> gridS_;
  std::vector<spin::Su2> gridU_, gridW_;
  std::vector<geometry::Vec3> labSum_, frameSum_, rollingSum_;
};

// The facts the image shows (resolveFacts, less the lines when labels are off
// or the layout has no ball view; marks need the ball view, the cone of B the
// twin), computed; null when none. Records the "facts" stage.
[[nodiscard]] std::shared_ptr<const SceneFacts> makeSceneFacts(const scene::SceneSpec& spec, const RollingModel& model);

// Rotation vector of the smaller rotation of q (angle ≤ π): the log used to
// unwrap increments.
[[nodiscard]] geometry::Vec3 incrementRotation(const spin::Su2& q);

}  // namespace rollspin::motion
