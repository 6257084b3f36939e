// Propagators for the rolling spinor  dU/ds = −(i/2) ω(s)·σ U,  U(0) = 1
// (ω = −B, see field.hpp), each marching a fixed grid of `steps` steps over
// [0, L] (distributed over the path's breakpoint segments so that grid nodes
// land on curvature jumps, each segment's share ∝ its ∫(|ω| + |d|) ds, so a
// short corner arc gets the steps its turn needs, not its length's share):
//   exact    closed form for constant κ_n, κ_g, τ_g (rotating-frame
//            construction):  U(s) = exp(−(i/2) s d₀·σ) exp(−(i/2) s e₀·σ),
//            d₀ = τ_g t₀ − κ_n u₀ + κ_g n₀ (Darboux vector), e₀ = ω₀ − d₀
//            = u₀/R − κ_g n₀. Evaluated directly at each s: no stepping.
//   magnus2  exponential midpoint: U ← exp(h A(s + h/2)) U.
//   magnus4  two Gauss points c = ½ ∓ √3/6 and one commutator:
//            Ω = (h/2)(A₁ + A₂) + (√3/12) h² [A₂, A₁].
//   rk4      classical Runge–Kutta on the raw spinor (not renormalised).
//   frame4   4th-order Magnus in the Darboux frame, where only κ_g drives the
//            motion, composed exactly with the frame (frame_propagator.hpp).
//   cf4      Blanes–Moan commutator-free, two exponentials at the Gauss points:
//            E = exp(h(a₂A₁ + a₁A₂)) exp(h(a₁A₁ + a₂A₂)), a₁,₂ = ¼ ± √3/6.
//   magnus6  three Gauss points c = ½ − √15/10, ½, ½ + √15/10 (Blanes–Casas–Ros):
//            α₁ = hA₂, α₂ = (√15/3)h(A₃ − A₁), α₃ = (10/3)h(A₃ − 2A₂ + A₁),
//            C₁ = [α₁, α₂], C₂ = −(1/60)[α₁, 2α₃ + C₁],
//            Ω = α₁ + α₃/12 + (1/240)[−20α₁ − α₃ + C₁, α₂ + C₂].
//   rk45     adaptive Dormand–Prince 5(4) on the raw spinor (the generic ODE
//            baseline; rtol = atol = tolerance per step), adaptive_march.hpp.
//   frame6a  adaptive magnus6 in the Darboux frame (frame4's factorisation, so
//            only κ_g drives the integrated part and constant κ_g is exact at
//            any h), error by step doubling, controlled per unit length so the
//            sum over the path stays ≤ tolerance (adaptive_march.hpp).
// In su(2) ≅ (R³, ×): A(ω) = −(i/2) ω·σ and [A(a), A(b)] = A(a × b).
// A joined path (a storyboard, ContactPath::pieces) is solved piece by piece
// and composed: U(s) = U_k(s − s_k) U_{k−1}(L_{k−1}) ⋯ U_1(L_1), each piece
// by the same method (so a corner between pieces costs nothing and exact
// applies when every piece has constant curvatures).
// A sample s between grid nodes is reached by one partial step from the
// preceding node, so samples never perturb the main march. The march
// multiplies blocks of 64 step elements pairwise before applying them, so
// round-off grows with the number of blocks, not of steps.
// The numeric core returns a status; it never prints or throws.
#pragma once

#include <algorithm>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/contact_path.hpp"
#include "spin/su2.hpp"

namespace rollspin::spin {

enum class Method { Exact, Magnus2, Magnus4, Rk4, Frame4, Cf4, Magnus6, Rk45, Frame6a };

[[nodiscard]] std::string_view methodName(Method m);
[[nodiscard]] std::optional<Method> parseMethod(std::string_view name);
[[nodiscard]] std::span<const Method> allMethods();
// Order of accuracy of the method (0 for exact).
[[nodiscard]] int methodOrder(Method m);
// Adaptive methods choose their own steps from a tolerance (rk45, frame6a).
[[nodiscard]] bool isAdaptive(Method m);
// Methods that multiply exact SU(2) elements (unitary to round-off).
[[nodiscard]] bool isGeometric(Method m);

enum class SolveStatus {
  Ok,
  NonFinite,                    // NaN or infinity appeared; the march stopped
  ExactNeedsConstantCurvature,  // exact asked for a path whose curvatures vary
  BadSteps,                     // steps < 1 for a stepping method
  BadTolerance,                 // an adaptive method needs a tolerance > 0
  StepSizeUnderflow,            // an adaptive method could not meet its tolerance
  StepLimit,                    // an adaptive method used up its step budget (setStepLimit)
};
[[nodiscard]] std::string_view statusMessage(SolveStatus s);

struct SolveStats {
  SolveStatus status = SolveStatus::Ok;
  Method method = Method::Magnus4;
  long long steps = 0;          // grid steps taken (0 for exact); accepted steps if adaptive
  long long rejectedSteps = 0;  // adaptive methods only
  double unitarityError = 0.0;  // max |‖U‖ − 1| over grid nodes and samples
  double seconds = 0.0;         // wall time of the march alone
  Su2 final;                    // U(L)
  // Samples handed to the sink: all of them, except that a run over a
  // forward-only slice stops at the first sample of a later piece.
  std::size_t samplesReported = 0;
  // A posteriori estimate of the rotation error of `final` in radians
  // (estimateError; NaN until one is made): the SO(3) distance to a second
  // solve at half the steps (fixed-step methods) or 32× the tolerance
  // (adaptive ones); a round-off bound for exact. `errorEstimateBasis` says
  // which, `errorEstimateSeconds` what it cost.
  double errorEstimate = std::numeric_limits<double>::quiet_NaN();
  std::string errorEstimateBasis;
  double errorEstimateSeconds = 0.0;
};

// The arc lengths at which a run reports U: an explicit non-decreasing list,
// a uniform grid s_j = j L/(count − 1) generated on the fly, so a
// timeline of 1e8 rows needs no 800 MB array, or any non-decreasing sequence
// generated on demand (an animation's frames merged with its trail grid).
class SampleArcLengths {
 public:
  SampleArcLengths() = default;
  SampleArcLengths(std::span<const double> explicitS) : explicit_(explicitS), count_(explicitS.size()) {}
  SampleArcLengths(const std::vector<double>& explicitS) : SampleArcLengths(std::span<const double>(explicitS)) {}
  // count ≥ 2 points from 0 to length inclusive (the last is exactly length).
  [[nodiscard]] static SampleArcLengths uniform(double length, std::size_t count);
  // count points, s_j = at(j). A run asks for j in non-decreasing order (it
  // may ask for the same j again), so `at` may be a forward-only cursor.
  [[nodiscard]] static SampleArcLengths generated(std::size_t count, std::function<double(std::size_t)> at);

  [[nodiscard]] std::size_t size() const { return count_; }
  [[nodiscard]] bool empty() const { return count_ == 0; }
  [[nodiscard]] double operator[](std::size_t j) const {
    if (!sliced_) return raw(j);
    const double s = raw(first_ + j);
    return s >= limit_ ? upper_ : std::clamp(s - offset_, 0.0, upper_);
  }
  // Samples first … first + count − 1 shifted by −offset into [0, upper]: a
  // piece's samples in its own arc length (joined paths). Samples at or
  // beyond `limit` (the next piece's start) map to exactly `upper`.
  [[nodiscard]] SampleArcLengths slice(std::size_t first, std::size_t count, double offset, double upper,
                                       double limit) const {
    SampleArcLengths out = *this;
    out.sliced_ = true;
    out.first_ = first_ + first;
    out.count_ = count;
    out.offset_ = offset;
    out.upper_ = upper;
    out.limit_ = limit;
    return out;
  }
  // Whether sample j of a slice lies at or beyond `limit` (a later piece's
  // samples, in a forward-only slice whose count could not be known).
  [[nodiscard]] bool beyondSlice(std::size_t j) const { return sliced_ && raw(first_ + j) >= limit_; }
  // A generated sequence may only be read forwards (see generated()).
  [[nodiscard]] bool forwardOnly() const { return static_cast<bool>(generator_); }

 private:
  [[nodiscard]] double raw(std::size_t j) const {
    if (generator_) return generator_(j);
    if (!uniform_) return explicit_[j];
    return j + 1 == total_ ? length_ : length_ * static_cast<double>(j) / static_cast<double>(total_ - 1);
  }
  std::span<const double> explicit_;
  std::function<double(std::size_t)> generator_;
  std::size_t count_ = 0;
  std::size_t total_ = 0;  // uniform grid: its full count
  bool uniform_ = false;
  double length_ = 0.0;
  bool sliced_ = false;
  std::size_t first_ = 0;
  double offset_ = 0.0, upper_ = 0.0, limit_ = 0.0;
};

// Called once per requested sample, in order: (sample index, s, U(s)).
using SampleSink = std::function<void(std::size_t, double, const Su2&)>;

class Propagator {
 public:
  // steps: for fixed-step methods; tolerance: for adaptive ones (isAdaptive).
  Propagator(const geometry::ContactPath& path, double ballRadius, Method method, long long steps,
             double tolerance = 0.0);

  // Marches [0, L] once and reports U at every s of sampleS (non-decreasing,
  // inside [0, L]). Also returns U(L) and the unitarity error.
  [[nodiscard]] SolveStats run(const SampleArcLengths& sampleS, const SampleSink& sink) const;
  // U(L) only.
  [[nodiscard]] SolveStats solveFinal() const { return run({}, {}); }

  // One step of the method from s to s + h.
  [[nodiscard]] Su2 step(const Su2& u, double s, double h) const;
  // Closed form U(s) (Method::Exact only; path must have constant curvatures).
  [[nodiscard]] Su2 closedForm(double s) const;
  [[nodiscard]] Vec3 omega(double s) const;

  [[nodiscard]] Method method() const { return method_; }
  [[nodiscard]] long long steps() const { return steps_; }
  [[nodiscard]] double tolerance() const { return tolerance_; }
  [[nodiscard]] const geometry::ContactPath& path() const { return path_; }
  [[nodiscard]] double ballRadius() const { return ballRadius_; }
  // The same march at another step count, sharing this one's segment
  // budgets (no second quadrature): the error estimate's coarse solve and
  // the automatic count's refinement.
  [[nodiscard]] Propagator withSteps(long long steps) const;
  // Adaptive methods stop with StepLimit after this many attempted steps
  // (default 2e9): a report can bound a hopeless cell's cost.
  void setStepLimit(long long attempts) { stepLimit_ = attempts; }

 private:
  // ∫(|ω| + |d|) ds per breakpoint segment, one list per piece (one list
  // for a plain path, empty when it is one segment); fixed-step methods only.
  using SegmentBudgets = std::vector<std::vector<double>>;
  Propagator(const geometry::ContactPath& path, double ballRadius, Method method, long long steps, double tolerance,
             std::shared_ptr<const SegmentBudgets> budgets);
  const geometry::ContactPath& path_;
  double ballRadius_;
  Method method_;
  long long steps_;
  double tolerance_;
  long long stepLimit_ = 2'000'000'000;
  std::shared_ptr<const SegmentBudgets> budgets_;  // shared by withSteps copies
  // A joined path (ContactPath::pieces): one propagator per piece, the steps
  // shared by each piece's ∫(|ω| + |d|) ds, the tolerance by its length.
  [[nodiscard]] SolveStats runPieces(const SampleArcLengths& sampleS, const SampleSink& sink) const;
  std::vector<long long> pieceSteps_;
  // A fixed-step march over one piece: its breakpoint segments [cuts_k,
  // cuts_{k+1}] and the steps each gets, shared by each segment's
  // ∫(|ω| + |d|) ds (segmentStepBudgets), at least one each.
  std::vector<double> cuts_;
  std::vector<long long> segmentSteps_;
  Vec3 d0_ = Vec3::Zero(), e0_ = Vec3::Zero();  // exact method's two rates
};

// Fills stats.errorEstimate / Basis / Seconds for a solve `stats` of `path`
// by `method` (steps, tolerance as given to the Propagator):
//   fixed step  ‖U_N − U_{N/2}‖ in SO(3), the same method at half the steps;
//               (2ᵖ − 1)× the error of U_N in the asymptotic range, so it
//               over-states by ~15 (order 4) to ~63 (order 6), never under;
//   adaptive    the same method at 32× the tolerance (about half the steps);
//   either      at twice the steps or 1/32 of the tolerance instead when the
//               coarser grid came out (nearly) the same (one step per
//               breakpoint segment already); rk4 and rk45, whose raw march
//               drifts by ~ε a step in both solves alike, add steps × ε;
//               every stepping method adds 48× the shared round-off floor
//               ε ∫(|ω| + |d|) ds;
//   exact       the round-off bound 8ε(1 + ∫(|ω| + |d|) ds) of the closed form.
// The second solve costs about half the first. A failed second solve leaves
// the estimate infinite.
void estimateError(const geometry::ContactPath& path, double ballRadius, Method method, long long steps,
                   double tolerance, SolveStats& stats);
// The same for a solve by `solved`, whose segment budgets the coarse solve
// shares; `stepBudget` = ∫(|ω| + |d|) ds when the caller has it (NaN:
// computed here).
void estimateError(const Propagator& solved, SolveStats& stats,
                   double stepBudget = std::numeric_limits<double>::quiet_NaN());

// Fractions c ∈ [0, 1] of a step at which a stepping method samples ω.
inline constexpr std::size_t kMaxNodes = 3;
[[nodiscard]] std::span<const double> stepNodes(Method m);
// The step U ↦ E U of a stepping method, from ω at its nodes (w[i] at
// s + c_i h). Every method here is linear in U from the left.
[[nodiscard]] Su2 stepElement(Method m, double h, const Vec3* w);
// magnus6's exponent Ω₆ (as a rotation vector) from ω at its three Gauss
// nodes c = ½ − √15/10, ½, ½ + √15/10.
[[nodiscard]] Vec3 magnus6Exponent(double h, const Vec3* w);

// s_j = j L / (count − 1), j = 0 … count − 1 (count ≥ 2).
[[nodiscard]] std::vector<double> uniformSamples(double length, std::size_t count);

}  // namespace rollspin::spin
