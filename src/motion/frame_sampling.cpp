#include "motion/frame_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "core/stage_log.hpp"
#include "motion/frame_poses.hpp"
#include "spin/field.hpp"

namespace rollspin::motion {

namespace {

bool isCircuit(const RollingModel& model) { return model.path->turns() > 0.0; }

}  // namespace

TrailGrid trailGrid(const scene::SceneSpec& spec, const RollingModel& model) {
  TrailGrid grid;
  grid.length = model.path->length();
  if (!spec.render.trails) return grid;
  // Fine enough that the Bloch trail is a smooth curve: ≥ 240 points over the
  // whole path, 120 per turn of the path or of the ball.
  const double ballTurns = spin::integratedFieldStrength(*model.path, model.ballRadius) / (2.0 * std::numbers::pi);
  const double points = std::max(240.0, 120.0 * std::max(ballTurns, model.path->turns()));
  grid.count = static_cast<std::size_t>(std::clamp(std::ceil(points), 1.0, 20000.0)) + 1;
  return grid;
}

std::vector<double> strobeArcLengths(const scene::SceneSpec& spec, const RollingModel& model) {
  std::vector<double> out;
  const long long n = spec.render.strobe;
  if (n <= 1) return out;
  StageLog::instance().record("strobe");
  const double length = model.path->length();
  // A closed circuit would repeat its start at s = L: spread N over [0, L).
  const double denominator = isCircuit(model) && std::abs(model.path->turns() - std::round(model.path->turns())) < 1e-9
                                 ? double(n)
                                 : double(n - 1);
  for (long long j = 0; j < n; ++j) out.push_back(std::min(length, length * double(j) / denominator));
  return out;
}

FrameSampling frameSampling(const scene::SceneSpec& spec, const RollingModel& model, double s) {
  FrameSampling out;
  const TrailGrid grid = trailGrid(spec, model);
  if (grid.count > 0) {
    StageLog::instance().record("trails");
    out.trail.push_back(grid.at(0));
    for (std::size_t i = 1; i < grid.count && grid.at(i) < s; ++i) out.trail.push_back(grid.at(i));
    out.trail.push_back(s);
  }
  out.strobe = strobeArcLengths(spec, model);
  return out;
}

std::vector<double> cutArcLengths(const RollingModel& model) {
  std::vector<double> out;
  std::optional<std::size_t> previous;
  for (const model::SegmentSpan& span : model.segments) {
    if (!(span.end > span.start)) continue;
    if (previous && span.surface != *previous) out.push_back(span.start);
    previous = span.surface;
  }
  return out;
}

FrameOrientations solveFrame(const scene::SceneSpec& spec, const RollingModel& model, double s) {
  StageLog::instance().record("solver");
  const FrameSampling sampling = frameSampling(spec, model, s);
  const std::vector<double> cuts = cutArcLengths(model);
  std::vector<double> all = sampling.trail;
  all.insert(all.end(), sampling.strobe.begin(), sampling.strobe.end());
  all.insert(all.end(), cuts.begin(), cuts.end());
  all.push_back(s);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  std::vector<spin::Su2> orientation(all.size());
  marchScene(spec, model, all, [&](std::size_t i, double, const spin::Su2& q) { orientation[i] = q; });
  auto lookup = [&](double x) {
    const auto it = std::lower_bound(all.begin(), all.end(), x);
    return OrientedSample{x, orientation[static_cast<std::size_t>(it - all.begin())]};
  };
  FrameOrientations frame;
  frame.current = lookup(s);
  for (double x : sampling.trail) frame.trail.push_back(lookup(x));
  for (double x : sampling.strobe) frame.strobe.push_back(lookup(x));
  for (double x : cuts) frame.cuts.push_back(lookup(x));
  return frame;
}

FrameClock clipClock(const scene::SceneSpec& spec, const RollingModel& model) {
  if (!spec.isStoryboard()) return FrameClock(model.path->length(), spec);
  return FrameClock(model.segments, spec);
}

StoryPlace storyPlaceAt(const RollingModel& model, double s) {
  StoryPlace place;
  for (std::size_t k = 0; k < model.segments.size(); ++k)
    if (model.segments[k].end > model.segments[k].start && model.segments[k].start <= s) place.segment = k;
  return place;
}

}  // namespace rollspin::motion
