#include "spin/propagator.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <chrono>
#include <cmath>

#include <fmt/format.h>
#include <Eigen/Geometry>
#include <limits>

#include "spin/adaptive_march.hpp"
#include "spin/block_kernel.hpp"
#include "spin/field.hpp"
#include "spin/frame_propagator.hpp"

namespace rollspin::spin {

namespace {
// The methods: one row each (name, order, adaptive, geometric). A new method
// is its enum value, its row here and its step (stepNodes / stepElement).
struct MethodRow {
  Method method;
  std::string_view name;
  int order;       // of accuracy (0: exact)
  bool adaptive;   // chooses its own steps from a tolerance
  bool geometric;  // multiplies exact SU(2) elements (unitary to round-off)
};
constexpr std::array<MethodRow, 9> kMethodTable{{
    {Method::Exact, "exact", 0, false, true},
    {Method::Magnus2, "magnus2", 2, false, true},
    {Method::Magnus4, "magnus4", 4, false, true},
    {Method::Rk4, "rk4", 4, false, false},
    {Method::Frame4, "frame4", 4, false, true},
    {Method::Cf4, "cf4", 4, false, true},
    {Method::Magnus6, "magnus6", 6, false, true},
    {Method::Rk45, "rk45", 5, true, false},
    {Method::Frame6a, "frame6a", 6, true, true},
}};
constexpr auto kMethods = [] {
  std::array<Method, kMethodTable.size()> out{};
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = kMethodTable[i].method;
  return out;
}();
const MethodRow& rowOf(Method m) {
  for (const auto& row : kMethodTable)
    if (row.method == m) return row;
  assert(false && "every Method has a row in kMethodTable");
  return kMethodTable[0];
}

// dU/ds = ½ (0, ω) ⊗ U in quaternion form, for the raw-spinor RK4.
Su2 derivative(const Vec3& w, const Su2& u) {
  const Su2 half{0.0, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z()};
  return half * u;
}
Su2 axpy(const Su2& u, double h, const Su2& k) { return {u.w + h * k.w, u.x + h * k.x, u.y + h * k.y, u.z + h * k.z}; }
constexpr std::size_t kBlock = kernel::kBlockSteps;
}  // namespace

std::string_view methodName(Method m) { return rowOf(m).name; }

std::optional<Method> parseMethod(std::string_view name) {
  for (const auto& row : kMethodTable)
    if (row.name == name) return row.method;
  return std::nullopt;
}

std::span<const Method> allMethods() { return kMethods; }
int methodOrder(Method m) { return rowOf(m).order; }
bool isAdaptive(Method m) { return rowOf(m).adaptive; }
bool isGeometric(Method m) { return rowOf(m).geometric; }

std::string_view statusMessage(SolveStatus s) {
  switch (s) {
    case SolveStatus::Ok: return "ok";
    case SolveStatus::NonFinite: return "the solution became NaN or infinite";
    case SolveStatus::ExactNeedsConstantCurvature:
      return "method 'exact' needs a path with constant curvatures (line, circle, parallel)";
    case SolveStatus::BadSteps: return "steps must be at least 1";
    case SolveStatus::BadTolerance: return "an adaptive method needs solver.tolerance > 0";
    case SolveStatus::StepSizeUnderflow:
      return "the adaptive step size underflowed: the tolerance is below what double precision can reach here";
    case SolveStatus::StepLimit: return "the adaptive method reached its step limit";
  }
  return "?";
}

Propagator::Propagator(const geometry::ContactPath& path, double ballRadius, Method method, long long steps,
                       double tolerance)
    : Propagator(path, ballRadius, method, steps, tolerance, nullptr) {}

Propagator::Propagator(const geometry::ContactPath& path, double ballRadius, Method method, long long steps,
                       double tolerance, std::shared_ptr<const SegmentBudgets> budgets)
    : path_(path),
      ballRadius_(ballRadius),
      method_(method),
      steps_(steps),
      tolerance_(tolerance),
      budgets_(std::move(budgets)) {
  const bool fixedStep = method_ != Method::Exact && !isAdaptive(method_);
  const auto pieces = path_.pieces();
  // ∫(|ω| + |d|) ds per breakpoint segment (per piece of a joined path), by
  // quadrature once: a propagator made by withSteps shares them.
  if (fixedStep && !budgets_) {
    auto computed = std::make_shared<SegmentBudgets>();
    if (!pieces.empty()) {
      for (const auto& piece : pieces) computed->push_back(segmentStepBudgets(*piece.path, ballRadius_));
    } else {
      // One segment needs no quadrature (all its steps are its own).
      std::size_t inside = 0;
      for (double b : path_.breakpoints()) inside += b > 0.0 && b < path_.length();
      computed->push_back(inside > 0 ? segmentStepBudgets(path_, ballRadius_) : std::vector<double>{});
    }
    budgets_ = std::move(computed);
  }
  if (!pieces.empty() && fixedStep) {
    // Steps go where the rotation and the frame's turning are: a tight
    // circle gets more of them than a line of the same length.
    std::vector<double> budget;
    double total = 0.0;
    for (const std::vector<double>& perSegment : *budgets_) {
      double sum = 0.0;  // in segment order from 0, as integratedStepBudget sums them
      for (double b : perSegment) sum += b;
      total += budget.emplace_back(sum);
    }
    for (double b : budget) {
      const double share = total > 0.0 ? b / total : 1.0 / static_cast<double>(pieces.size());
      pieceSteps_.push_back(std::max<long long>(1, std::llround(static_cast<double>(steps_) * share)));
    }
  }
  if (pieces.empty() && fixedStep && steps_ >= 1) {
    // Breakpoint segments get steps by ∫(|ω| + |d|) ds, not by length: on a
    // polyline a corner arc of radius r turns the frame by its whole angle
    // in a length ∝ r, and a share by length left it a step or two (1e-7
    // rad at r = 0.004 on 6,000 steps). One segment needs no quadrature.
    const double length = path_.length();
    cuts_.push_back(0.0);
    for (double b : path_.breakpoints())
      if (b > 0.0 && b < length) cuts_.push_back(b);
    cuts_.push_back(length);
    if (cuts_.size() == 2) {
      segmentSteps_.push_back(steps_);
    } else {
      const std::vector<double>& budget = budgets_->front();
      double total = 0.0;
      for (double b : budget) total += b;
      for (std::size_t k = 0; k + 1 < cuts_.size(); ++k) {
        const double share = total > 0.0 && std::isfinite(total) ? budget[k] / total
                                                                 : (cuts_[k + 1] - cuts_[k]) / std::max(length, 1e-300);
        segmentSteps_.push_back(std::max<long long>(1, std::llround(static_cast<double>(steps_) * share)));
      }
    }
  }
  if (method_ == Method::Exact && path_.hasConstantCurvatures()) {
    const geometry::DarbouxSample f0 = path_.at(0.0);
    d0_ = geometry::darbouxVector(f0);
    e0_ = angularVelocity(f0, ballRadius_) - d0_;
  }
}

Propagator Propagator::withSteps(long long steps) const {
  return Propagator(path_, ballRadius_, method_, steps, tolerance_, budgets_);
}

Vec3 Propagator::omega(double s) const { return angularVelocity(path_.at(s), ballRadius_); }

Su2 Propagator::closedForm(double s) const { return expRotation(s * d0_) * expRotation(s * e0_); }

Su2 Propagator::step(const Su2& u, double s, double h) const {
  if (method_ == Method::Exact) return closedForm(s + h);
  if (method_ == Method::Frame4) return frame4Element(path_, ballRadius_, s, h) * u;
  if (isAdaptive(method_)) return adaptiveStep(path_, ballRadius_, method_, u, s, h);
  const std::span<const double> nodes = stepNodes(method_);
  Vec3 w[kMaxNodes];
  for (std::size_t i = 0; i < nodes.size(); ++i) w[i] = omega(s + nodes[i] * h);
  return stepElement(method_, h, w) * u;
}

std::span<const double> stepNodes(Method m) {
  static constexpr double kMidpoint[] = {0.5};
  static constexpr double kGauss2[] = {0.5 - 0.28867513459481288225, 0.5 + 0.28867513459481288225};  // ½ ∓ √3/6
  static constexpr double kSimpson[] = {0.0, 0.5, 1.0};
  static constexpr double kGauss3[] = {0.5 - 0.38729833462074168852, 0.5, 0.5 + 0.38729833462074168852};  // √15/10
  switch (m) {
    case Method::Magnus2: return kMidpoint;
    case Method::Magnus4:
    case Method::Cf4: return kGauss2;
    case Method::Rk4: return kSimpson;
    case Method::Magnus6: return kGauss3;
    case Method::Exact:
    case Method::Frame4:  // frame4 samples the frame, not ω (frame_propagator.hpp)
    case Method::Rk45:
    case Method::Frame6a: break;  // adaptive: their own march (adaptive_march.hpp)
  }
  return {};
}

// Every stepper here maps U ↦ E U with E independent of U (the equation is
// linear and all terms multiply from the left), so a step is one SU(2)
// element built from ω at the method's nodes.
Su2 stepElement(Method m, double h, const Vec3* w) {
  switch (m) {
    case Method::Magnus2: return expRotation(h * w[0]);
    case Method::Magnus4: {
      const Vec3 magnus = (0.5 * h) * (w[0] + w[1]) + (0.14433756729740644113 * h * h) * w[1].cross(w[0]);  // √3/12
      return expRotation(magnus);
    }
    case Method::Rk4: {
      const Su2 one = Su2::identity();
      const Su2 k1 = derivative(w[0], one);
      const Su2 k2 = derivative(w[1], axpy(one, 0.5 * h, k1));
      const Su2 k3 = derivative(w[1], axpy(one, 0.5 * h, k2));
      const Su2 k4 = derivative(w[2], axpy(one, h, k3));
      return {1.0 + h / 6.0 * (k1.w + 2 * k2.w + 2 * k3.w + k4.w), h / 6.0 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x),
              h / 6.0 * (k1.y + 2 * k2.y + 2 * k3.y + k4.y), h / 6.0 * (k1.z + 2 * k2.z + 2 * k3.z + k4.z)};
    }
    case Method::Cf4: {
      // Blanes–Moan: the later exponential weighs the later node more; the
      // BCH product reproduces magnus4's commutator term to O(h⁵).
      constexpr double a1 = 0.25 + 0.28867513459481288225, a2 = 0.25 - 0.28867513459481288225;  // ¼ ± √3/6
      return expRotation(h * (a2 * w[0] + a1 * w[1])) * expRotation(h * (a1 * w[0] + a2 * w[1]));
    }
    case Method::Magnus6: return expRotation(magnus6Exponent(h, w));
    case Method::Exact:
    case Method::Frame4:
    case Method::Rk45:
    case Method::Frame6a: break;
  }
  return Su2::identity();
}

// In su(2) ≅ (R³, ×) every commutator is a cross product, so the two nested
// commutators of the sixth-order formula cost a few flops.
Vec3 magnus6Exponent(double h, const Vec3* w) {
  const Vec3 a1 = h * w[1];
  const Vec3 a2 = (1.2909944487358056284 * h) * (w[2] - w[0]);  // √15/3
  const Vec3 a3 = (10.0 / 3.0 * h) * (w[2] - 2.0 * w[1] + w[0]);
  const Vec3 c1 = a1.cross(a2);
  const Vec3 c2 = (-1.0 / 60.0) * a1.cross(2.0 * a3 + c1);
  return a1 + a3 / 12.0 + (1.0 / 240.0) * (-20.0 * a1 - a3 + c1).cross(a2 + c2);
}

namespace {
// E[m−1] ⋯ E[1] E[0] by pairwise products: round-off grows like log m
// instead of m, and the independent products pipeline well.
Su2 orderedProduct(Su2* e, std::size_t m) {
  for (std::size_t stride = 1; stride < m; stride *= 2)
    for (std::size_t i = 0; i + stride < m; i += 2 * stride) e[i] = e[i + stride] * e[i];
  return e[0];
}
}  // namespace


SolveStats Propagator::runPieces(const SampleArcLengths& sampleS, const SampleSink& sink) const {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto pieces = path_.pieces();
  SolveStats stats;
  stats.method = method_;
  if (method_ != Method::Exact && !isAdaptive(method_) && steps_ < 1) {
    stats.status = SolveStatus::BadSteps;
    return stats;
  }
  Su2 before = Su2::identity();  // U_{k−1}(L_{k−1}) ⋯ U_1(L_1)
  std::size_t next = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const geometry::ContactPath& piece = *pieces[k].path;
    const double pieceLength = piece.length();
    const bool last = k + 1 == pieces.size();
    // This piece's samples: those before the next piece's start (the last
    // piece takes the rest). A random-access list is bisected (it is
    // non-decreasing); a forward-only one is handed over whole, and the
    // run stops at the first sample beyond the piece (beyondSlice).
    std::size_t end = sampleS.size();
    const bool bisect = !last && !sampleS.forwardOnly();
    if (bisect) {
      std::size_t lo = next, hi = sampleS.size();
      while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (sampleS[mid] < pieces[k + 1].start) lo = mid + 1;
        else hi = mid;
      }
      end = lo;
    }
    const SampleArcLengths mine =
        sampleS.slice(next, end - next, pieces[k].start, pieceLength, last ? INFINITY : pieces[k + 1].start);
    const long long steps = pieceSteps_.empty() ? 0 : pieceSteps_[k];
    const double tolerance = tolerance_ * pieceLength / std::max(path_.length(), 1e-300);
    // The piece's segment budgets were computed once (the constructor).
    Propagator sub(piece, ballRadius_, method_, steps, tolerance,
                   budgets_ ? std::make_shared<const SegmentBudgets>(1, (*budgets_)[k]) : nullptr);
    sub.setStepLimit(stepLimit_);
    // A forward-only slice ends at the first sample of a later piece: the
    // run stops there (its U is this piece's U(L_k), that sample reading as
    // L_k) and the next piece starts from it.
    const SolveStats part = sub.run(mine, [&](std::size_t j, double, const Su2& u) {
      if (sink) sink(next + j, sampleS[next + j], u * before);
    });
    stats.steps += part.steps;
    stats.rejectedSteps += part.rejectedSteps;
    stats.unitarityError = std::max(stats.unitarityError, part.unitarityError);
    if (part.status != SolveStatus::Ok) {
      stats.status = part.status;
      break;
    }
    before = part.final * before;
    next += part.samplesReported;
  }
  stats.final = before;
  stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return stats;
}

namespace {
// The unitarity drift so far; false once U is no longer finite.
bool trackUnitarity(SolveStats& stats, const Su2& u) {
  stats.unitarityError = std::max(stats.unitarityError, std::abs(u.norm() - 1.0));
  return u.isFinite();
}

// Method::Exact: U at every sample and at L from the closed form.
SolveStatus closedFormSamples(const Propagator& p, const SampleArcLengths& sampleS, const SampleSink& sink,
                              SolveStats& stats) {
  for (std::size_t j = 0; j < sampleS.size() && !sampleS.beyondSlice(j); ++j, ++stats.samplesReported) {
    const Su2 u = p.closedForm(sampleS[j]);
    if (!trackUnitarity(stats, u)) return SolveStatus::NonFinite;
    if (sink) sink(j, sampleS[j], u);
  }
  stats.final = p.closedForm(p.path().length());
  if (!trackUnitarity(stats, stats.final)) return SolveStatus::NonFinite;
  return SolveStatus::Ok;
}

// One block of a fixed-step march: steps k0 … k0 + m − 1 of the segment
// [a, b] cut into n steps of h, the first starting at sBlock.
struct MarchBlock {
  double a, b, h;
  long long n, k0;
  std::size_t m;
  double sBlock;
};

// ω at the nodes of the block's first step: on a rigid field, the
// segment's first-step values turned by Rot(d, k₀ h |d|) (one direct
// rotation per block, no accumulation); otherwise evaluated (and on a rigid
// field kept as the segment's first-step values).
void blockAnchors(const Propagator& p, const MarchBlock& blk, std::span<const double> nodes, bool rigidField,
                  const Vec3& darboux, const Vec3& darbouxAxis, Vec3* firstAnchors, Vec3* anchors) {
  const std::size_t nodeCount = nodes.size();
  if (rigidField && blk.k0 > 0) {
    const Mat3 turn =
        Eigen::AngleAxisd(static_cast<double>(blk.k0) * blk.h * darboux.norm(), darbouxAxis).toRotationMatrix();
    for (std::size_t i = 0; i < nodeCount; ++i) anchors[i] = turn * firstAnchors[i];
  } else {
    for (std::size_t i = 0; i < nodeCount; ++i) anchors[i] = p.omega(blk.sBlock + nodes[i] * blk.h);
    if (rigidField) std::copy(anchors, anchors + nodeCount, firstAnchors);
  }
}

// Rot(d, j h |d|), step j's power of the rigid field's rotation.
Mat3 rotationPowerOf(const kernel::RotationPowers& powers, std::size_t j) {
  // Step j sits at position 4i + c with j = 16c + i (see block_kernel.hpp).
  const std::size_t p = (j % kernel::kChainLength) * kernel::kChains + j / kernel::kChainLength;
  Mat3 r;
  for (int k = 0; k < 9; ++k) r(k / 3, k % 3) = powers.m[k][p];
  return r;
}

// The step elements of a block, from ω at each step's nodes (turned from
// the anchors on a rigid field, evaluated otherwise).
void fillStepElements(const Propagator& p, const MarchBlock& blk, std::span<const double> nodes, bool rigidField,
                      const kernel::RotationPowers& powers, const Vec3* anchors,
                      std::array<Vec3, kBlock * kMaxNodes>& w, std::array<Su2, kBlock>& elements) {
  const double h = blk.h;
  for (std::size_t j = 0; j < blk.m; ++j) {
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      w[j * kMaxNodes + i] = rigidField ? Vec3(rotationPowerOf(powers, j) * anchors[i])
                                        : p.omega(blk.sBlock + (static_cast<double>(j) + nodes[i]) * h);
    }
    if (p.method() == Method::Frame4) {
      // Each step's end node is the next step's start node, bit for
      // bit, so the frame factors Φ(s_{j+1}) Φ(s_j)† telescope: with
      // s + h recomputed per step the two differ by ε·s and the
      // mismatch accumulated to 6e-4 over 1e6 lollipop turns. The
      // body rotation keeps the uniform h (at R/r = 1e-6 an angle of
      // |g| h ≈ 1e5 per step would feel the rounding of sNext − sj).
      const long long k = blk.k0 + static_cast<long long>(j);
      const double sj = blk.a + static_cast<double>(k) * h;
      const double sNext = k + 1 == blk.n ? blk.b : blk.a + static_cast<double>(k + 1) * h;
      elements[j] = frame4Element(p.path(), p.ballRadius(), sj, h, sNext);
    } else {
      elements[j] = stepElement(p.method(), h, &w[j * kMaxNodes]);
    }
  }
}

// Samples inside a block (s < sBlockEnd): walk the prefix products from the
// block's start U, then one partial step from the node before each sample.
// They never feed back into the march, so U(L) does not depend on them.
// False when a sample's U is not finite.
bool reportBlockSamples(const Propagator& p, const MarchBlock& blk, double sBlockEnd,
                        const std::array<Su2, kBlock>& elements, const Su2& u, const SampleArcLengths& sampleS,
                        const SampleSink& sink, std::size_t& next, SolveStats& stats) {
  Su2 prefix = u;
  std::size_t node = 0;
  while (next < sampleS.size() && !sampleS.beyondSlice(next) && sampleS[next] < sBlockEnd) {
    const double sj = std::max(sampleS[next], blk.sBlock);
    const std::size_t target =
        std::min<std::size_t>(blk.m - 1, static_cast<std::size_t>(std::max(0.0, (sj - blk.sBlock) / blk.h)));
    for (; node < target; ++node) prefix = elements[node] * prefix;
    const double sNode = blk.sBlock + static_cast<double>(node) * blk.h;
    const double dh = sj - sNode;
    const Su2 uj = dh <= 0.0 ? prefix : p.step(prefix, sNode, dh);
    if (!trackUnitarity(stats, uj)) return false;
    if (sink) sink(next, sampleS[next], uj);
    ++next;
  }
  return true;
}
}  // namespace

SolveStats Propagator::run(const SampleArcLengths& sampleS, const SampleSink& sink) const {
  if (!path_.pieces().empty()) return runPieces(sampleS, sink);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  SolveStats stats;
  stats.method = method_;
  auto finish = [&](SolveStatus status) {
    stats.status = status;
    stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return stats;
  };

  if (method_ == Method::Exact) {
    if (!path_.hasConstantCurvatures()) return finish(SolveStatus::ExactNeedsConstantCurvature);
    return finish(closedFormSamples(*this, sampleS, sink, stats));
  }
  if (isAdaptive(method_)) {
    if (!(tolerance_ > 0.0)) return finish(SolveStatus::BadTolerance);
    SolveStats adaptive = adaptiveRun(path_, ballRadius_, method_, tolerance_, stepLimit_, sampleS, sink);
    adaptive.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return adaptive;
  }
  if (steps_ < 1) return finish(SolveStatus::BadSteps);

  // Segment boundaries and steps: set by the constructor (cuts_, segmentSteps_).
  const std::vector<double>& cuts = cuts_;

  const std::span<const double> nodes = stepNodes(method_);
  // On a path of constant curvatures the frame turns rigidly about the fixed
  // Darboux vector d, so ω(s + jh) = Rot(d, j h |d|) ω(s) exactly: the field
  // at a block's nodes is one direct evaluation per node and a precomputed
  // rotation per step (no trigonometry inside the block).
  const bool rigidField = path_.hasConstantCurvatures();
  const Vec3 darboux = rigidField ? geometry::darbouxVector(path_.at(0.0)) : Vec3::Zero();
  const Vec3 darbouxAxis = darboux.norm() > 0.0 ? Vec3(darboux.normalized()) : Vec3::UnitZ();
  Vec3 firstAnchors[kMaxNodes];
  const bool geometric = isGeometric(method_);  // unit step elements
  const bool vectorKernel = rigidField && (method_ == Method::Magnus2 || method_ == Method::Magnus4);

  std::array<Su2, kBlock> elements;
  std::array<Vec3, kBlock * kMaxNodes> w;
  kernel::RotationPowers powers;
  Su2 u = Su2::identity();
  std::size_t next = 0;

  for (std::size_t seg = 0; seg + 1 < cuts.size(); ++seg) {
    const double a = cuts[seg], b = cuts[seg + 1];
    const long long n = segmentSteps_[seg];
    const double h = (b - a) / static_cast<double>(n);
    if (rigidField) kernel::fillRotationPowers(powers, darboux, h);
    for (long long k0 = 0; k0 < n; k0 += static_cast<long long>(kBlock)) {
      const std::size_t m = static_cast<std::size_t>(std::min<long long>(kBlock, n - k0));
      const double sBlock = a + static_cast<double>(k0) * h;
      const double sBlockEnd = (k0 + static_cast<long long>(m) == n) ? b : sBlock + static_cast<double>(m) * h;
      const bool lastBlock = seg + 2 == cuts.size() && k0 + static_cast<long long>(m) == n;
      const bool samplesHere = next < sampleS.size() && !sampleS.beyondSlice(next) && sampleS[next] < sBlockEnd;
      const bool useKernel = vectorKernel && m == kBlock;
      const MarchBlock blk{a, b, h, n, k0, m, sBlock};

      Vec3 anchors[kMaxNodes];
      blockAnchors(*this, blk, nodes, rigidField, darboux, darbouxAxis, firstAnchors, anchors);
      // Scalar step elements: needed for partial blocks, varying fields and
      // for walking to samples; the vector kernel makes its own.
      if (!useKernel || samplesHere) fillStepElements(*this, blk, nodes, rigidField, powers, anchors, w, elements);
      if (samplesHere && !reportBlockSamples(*this, blk, sBlockEnd, elements, u, sampleS, sink, next, stats))
        return finish(SolveStatus::NonFinite);

      const Su2 block = useKernel ? kernel::rigidMagnusBlock(methodOrder(method_), h, anchors, powers)
                                  : orderedProduct(elements.data(), m);
      u = block * u;
      // A product of unit elements is unit: project the round-off in the norm
      // away once per block, so it cannot accumulate over millions of steps
      // (the direction on S³, i.e. the orientation, is untouched). rk4 is the
      // raw baseline and keeps its drift.
      if (geometric) {
        const double norm = u.norm();
        u = {u.w / norm, u.x / norm, u.y / norm, u.z / norm};
      }
      stats.steps += static_cast<long long>(m);
      if (!trackUnitarity(stats, u)) return finish(SolveStatus::NonFinite);
      if (lastBlock) {
        for (; next < sampleS.size() && !sampleS.beyondSlice(next); ++next) {
          if (sink) sink(next, sampleS[next], u);
        }
      }
    }
  }
  stats.final = u;
  stats.samplesReported = next;
  return finish(SolveStatus::Ok);
}

void estimateError(const geometry::ContactPath& path, double ballRadius, Method method, long long steps,
                   double tolerance, SolveStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  estimateError(Propagator(path, ballRadius, method, steps, tolerance), stats);
  stats.errorEstimateSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void estimateError(const Propagator& solved, SolveStats& stats, double stepBudget) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const geometry::ContactPath& path = solved.path();
  const double ballRadius = solved.ballRadius(), tolerance = solved.tolerance();
  const Method method = solved.method();
  const long long steps = solved.steps();
  if (!std::isfinite(stepBudget)) stepBudget = integratedStepBudget(path, ballRadius);
  if (method == Method::Exact) {
    // No grid to halve: the closed form's error is the rounding of its two
    // exponentials' angles, at most a few ε per radian they turn.
    stats.errorEstimate = 8.0 * std::numeric_limits<double>::epsilon() * (1.0 + stepBudget);
    stats.errorEstimateBasis = "round-off bound of the closed form, 8 eps (1 + integral of |w| + |d| ds)";
  } else {
    const bool adaptive = isAdaptive(method);
    long long otherSteps = std::max<long long>(1, steps / 2);
    double otherTolerance = 32.0 * tolerance;
    // Fixed steps: the same segment budgets, no second quadrature.
    SolveStats other = adaptive ? Propagator(path, ballRadius, method, 0, otherTolerance).solveFinal()
                                : solved.withSteps(otherSteps).solveFinal();
    const char* which = adaptive ? "32x the tolerance" : "half the steps";
    // A grid that could not coarsen (each breakpoint segment already down to
    // one step, or an adaptive march held by something other than its
    // tolerance) would compare a solve with itself: compare with a finer one.
    if (other.status == SolveStatus::Ok && 4 * other.steps > 3 * stats.steps) {
      otherSteps = 2 * steps;
      otherTolerance = tolerance / 32.0;
      other = adaptive ? Propagator(path, ballRadius, method, 0, otherTolerance).solveFinal()
                       : solved.withSteps(otherSteps).solveFinal();
      which = adaptive ? "1/32 of the tolerance" : "twice the steps";
    }
    stats.errorEstimate = other.status == SolveStatus::Ok ? rotationDistance(stats.final, other.final)
                                                          : std::numeric_limits<double>::infinity();
    // A raw (non-unitary) march rounds by ~ε per step, and that drift is
    // shared by both solves, so their difference cannot see it: add it.
    if (!isGeometric(method))
      stats.errorEstimate += std::numeric_limits<double>::epsilon() * static_cast<double>(stats.steps);
    stats.errorEstimateBasis =
        adaptive ? fmt::format("difference to {} at {} ({:g})", methodName(method), which, otherTolerance)
                 : fmt::format("difference to {} at {} ({})", methodName(method), which, otherSteps);
    if (!isGeometric(method)) stats.errorEstimateBasis += " + steps x eps (round-off of a raw march)";
    // Round-off that both solves share (the rounding of the field and of
    // each step's angle, ~ε per radian turned) is invisible to their
    // difference too: add 48 times the floor ε ∫(|ω| + |d|) ds. It dominates only
    // where the error itself is at that floor (1e6 turns: 8e-10).
    // 48ε: the stress suite's tight turns (κ_g = 1e4) leave magnus4 1.3e-12
    // off with a difference of 1.3e-13 and a floor of 7e-15 (needs ≥ 37ε),
    // while frame6a on the plane at R/r = 1e-6 is 7.9e-11 off with a floor
    // of 1.4e-9 (the 1000× bound allows ≤ 56ε). On the random default
    // solves of tests/motion/automatic_accuracy_test.cpp (errors 1e-14 to
    // 4e-13) this term is a sizeable share of the estimate, error/estimate
    // ≤ 0.06 there (docs/solver.md).
    stats.errorEstimate += 48.0 * std::numeric_limits<double>::epsilon() * stepBudget;
    stats.errorEstimateBasis += " + the round-off floor 48 eps x integral(|w| + |d|) ds";
  }
  stats.errorEstimateSeconds = std::chrono::duration<double>(Clock::now() - start).count();
}

SampleArcLengths SampleArcLengths::uniform(double length, std::size_t count) {
  SampleArcLengths grid;
  grid.uniform_ = true;
  grid.count_ = std::max<std::size_t>(count, 2);
  grid.total_ = grid.count_;
  grid.length_ = length;
  return grid;
}

SampleArcLengths SampleArcLengths::generated(std::size_t count, std::function<double(std::size_t)> at) {
  SampleArcLengths samples;
  samples.generator_ = std::move(at);
  samples.count_ = count;
  return samples;
}

std::vector<double> uniformSamples(double length, std::size_t count) {
  std::vector<double> s(std::max<std::size_t>(count, 2));
  const double n = static_cast<double>(s.size() - 1);
  for (std::size_t j = 0; j < s.size(); ++j) s[j] = length * static_cast<double>(j) / n;
  s.back() = length;
  return s;
}

}  // namespace rollspin::spin
