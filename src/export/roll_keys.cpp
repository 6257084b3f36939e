#include <algorithm>
#include <cmath>
#include <vector>

#include "core/stage_log.hpp"
#include "export/gltf_export.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/solve_job.hpp"
#include "spin/field.hpp"
#include "spin/propagator.hpp"

namespace rollspin::gltf {

namespace {

using geometry::Vec3;
using spin::Su2;

// Bisection stops after this many rounds even if a midpoint still fails
// (float32 times then sit next to each other: no midpoint is left).
constexpr int kMaxRounds = 64;

// The quaternion as the file holds it: float32 components.
Su2 asStored(const Su2& q) { return {double(float(q.w)), double(float(q.x)), double(float(q.y)), double(float(q.z))}; }

Su2 normalised(const Su2& q) {
  const double n = q.norm();
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// glTF's slerp (the spec's, on the shorter arc) between two unit quaternions.
Su2 slerp(const Su2& a, Su2 b, double x) {
  double d = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
  if (d < 0.0) {
    b = -b;
    d = -d;
  }
  const double angle = std::acos(std::min(1.0, d));
  double wa = 1.0 - x, wb = x;
  if (angle > 1e-12) {
    wa = std::sin((1.0 - x) * angle) / std::sin(angle);
    wb = std::sin(x * angle) / std::sin(angle);
  }
  return normalised({wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z});
}

struct Key {
  float seconds = 0.0f;
  double s = 0.0;
  Su2 q;
};

// Where a storyboard changes surface the path jumps at one s, the join: a
// time at the join that the clip still shows on the earlier surface (the
// hold before the cut, up to and with the whole frame before the new
// surface's motion) is keyed a hair before it (this share of L), the ball
// where that surface's path ends, as the renders show it; a fractional
// frame f belongs to the whole frame ⌈f⌉ (it leads up to it).
constexpr double kJoinGap = 1e-10;

// The clock as a function of float32 seconds (what the file can say).
struct Timing {
  const motion::FrameClock& clock;
  const model::RollingModel& model;
  double fps;
  [[nodiscard]] double frameOf(float seconds) const { return double(seconds) * fps; }
  [[nodiscard]] double arcLengthAt(float seconds) const {
    const double frame = std::clamp(frameOf(seconds), 0.0, double(clock.frameCount() - 1));
    const double s = clock.arcLengthAt(frame);
    if (model.segments.empty()) return s;
    const std::size_t shown = clock.place(static_cast<long long>(std::ceil(frame - kFrameSlack))).segment;
    const std::size_t atS = motion::storyPlaceAt(model, s).segment;
    const bool earlierSurface = shown < model.segments.size() && atS < model.segments.size() &&
                                model.segments[shown].surface != model.segments[atS].surface;
    return earlierSurface ? std::max(0.0, s - kJoinGap * model.path->length()) : s;
  }
};

// The fractional frame where the clock shows s inside [f0, f1] (s(f) is
// non-decreasing there): bisection to double precision.
double frameShowing(const motion::FrameClock& clock, double s, double f0, double f1) {
  for (int i = 0; i < 200 && f1 - f0 > 1e-12 * std::max(1.0, f1); ++i) {
    const double mid = 0.5 * (f0 + f1);
    (clock.arcLengthAt(mid) < s ? f0 : f1) = mid;
  }
  return f1;
}

// The first keys: every whole frame of every motion, its bounds, and the
// frames that show each corner or joint of the path.
std::vector<float> initialTimes(const Timing& timing, const model::RollingModel& model) {
  const motion::FrameClock& clock = timing.clock;
  const std::vector<double> bounds = clock.motionBounds();
  std::vector<double> corners = model.path->breakpoints();
  for (const model::SegmentSpan& span : model.segments) corners.insert(corners.end(), {span.start, span.end});
  std::vector<double> frames = bounds;
  for (std::size_t b = 0; b + 1 < bounds.size(); ++b) {
    const double f0 = bounds[b], f1 = bounds[b + 1];
    const double s0 = clock.arcLengthAt(f0), s1 = clock.arcLengthAt(f1);
    if (s1 <= s0) continue;  // a hold: its two ends are enough
    for (double f = std::ceil(f0); f < f1; f += 1.0) frames.push_back(f);
    for (const double c : corners)
      if (c > s0 && c < s1) frames.push_back(frameShowing(clock, c, f0, f1));
  }
  std::vector<float> times;
  for (const double f : frames) times.push_back(float(f / timing.fps));
  // A key just after each motion bound too: where the surface changes the
  // ball jumps there (the bound keyed on the earlier surface, the next
  // float time on the new one).
  for (const double f : bounds)
    if (f < double(clock.frameCount() - 1)) times.push_back(secondsJustAfter(f, timing.fps));
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

// Solves at the keys' arc lengths (non-decreasing with their times) in one
// march of the scene's own solver, as a render's frames are solved.
void solveKeys(const spin::Propagator& propagator, const scene::SceneSpec& spec, std::vector<Key*>& keys) {
  std::vector<double> s;
  s.reserve(keys.size());
  for (const Key* k : keys) s.push_back(k->s);
  const spin::SolveStats stats =
      propagator.run(spin::SampleArcLengths(s), [&](std::size_t i, double, const Su2& q) { keys[i]->q = q; });
  if (stats.status != spin::SolveStatus::Ok)
    throw runtimeError(spec.where("solver.method"), "solver failed: {}", spin::statusMessage(stats.status));
}

// Bisection in time, one march a round: a midpoint whose slerp (from the
// stored float32 keys) is off the solver's q by more than the tolerance
// becomes a key, and both halves are checked next round.
std::vector<Key> bisect(std::vector<Key> keys, const Timing& timing, const spin::Propagator& propagator,
                        const scene::SceneSpec& spec) {
  std::vector<std::size_t> pending(keys.size() > 1 ? keys.size() - 1 : 0);
  for (std::size_t i = 0; i < pending.size(); ++i) pending[i] = i;  // interval i: keys i, i + 1
  for (int round = 0; round < kMaxRounds && !pending.empty(); ++round) {
    std::vector<Key> mids;
    std::vector<std::size_t> at;
    for (const std::size_t i : pending) {
      const float t = float(0.5 * (double(keys[i].seconds) + double(keys[i + 1].seconds)));
      if (t <= keys[i].seconds || t >= keys[i + 1].seconds) continue;
      mids.push_back({t, timing.arcLengthAt(t), Su2{}});
      at.push_back(i);
    }
    std::vector<Key*> solving;
    for (Key& m : mids) solving.push_back(&m);
    if (!solving.empty()) solveKeys(propagator, spec, solving);
    std::vector<Key> next;
    std::vector<std::size_t> nextPending;
    std::size_t m = 0;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      next.push_back(keys[i]);
      if (m >= at.size() || at[m] != i) continue;
      const Key& a = keys[i];
      const Key& b = keys[i + 1];
      const double x = (double(mids[m].seconds) - double(a.seconds)) / (double(b.seconds) - double(a.seconds));
      const Su2 between = slerp(normalised(asStored(a.q)), normalised(asStored(b.q)), x);
      if (spin::rotationDistance(between, mids[m].q) > kMidpointTolerance) {
        nextPending.push_back(next.size() - 1);
        next.push_back(mids[m]);
        nextPending.push_back(next.size() - 1);
      }
      ++m;
    }
    keys = std::move(next);
    pending = std::move(nextPending);
  }
  return keys;
}

}  // namespace

float secondsJustAfter(double frame, double fps) {
  float t = float((frame + kFrameSlack) / fps);  // then up by ulps, a few at most
  while (double(t) * fps - frame <= kFrameSlack) t = std::nextafter(t, 1e30f);
  return t;
}

RollKeys rollKeys(const scene::SceneSpec& spec, const model::RollingModel& model) {
  StageLog::instance().record("gltf-keys");
  const motion::FrameClock clock = motion::clipClock(spec, model);
  const Timing timing{clock, model, clock.fps().value()};
  const motion::SolverChoice choice = motion::chooseSolver(spec, model);
  const spin::Propagator propagator(*model.path, model.ballRadius, choice.method, choice.steps, choice.tolerance);
  std::vector<Key> keys;
  for (const float t : initialTimes(timing, model)) keys.push_back({t, timing.arcLengthAt(t), Su2{}});
  std::vector<Key*> all;
  for (Key& k : keys) all.push_back(&k);
  solveKeys(propagator, spec, all);
  keys = bisect(std::move(keys), timing, propagator, spec);

  RollKeys out;
  const double R = model.ballRadius;
  for (const Key& k : keys) {
    const geometry::DarbouxSample f = model.path->at(k.s);
    const Vec3 b = spin::fieldB(f, R);
    out.seconds.push_back(k.seconds);
    out.arcLength.push_back(k.s);
    out.rotation.push_back(k.q);
    out.centre.push_back(f.centre(R));
    out.field.push_back(b.norm() > 0.0 ? Vec3(b.normalized()) : Vec3(Vec3::UnitZ()));
  }
  return out;
}

}  // namespace rollspin::gltf
