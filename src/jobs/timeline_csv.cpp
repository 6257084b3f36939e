#include "jobs/timeline_csv.hpp"

#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "spin/field.hpp"

namespace rollspin::jobs {

using namespace rollspin::model;
using namespace rollspin::motion;

namespace {

// (start s, segment number from 1) of each motion of a storyboard; empty otherwise.
std::vector<std::pair<double, std::size_t>> motionStarts(const RollingModel& model) {
  std::vector<std::pair<double, std::size_t>> motions;
  for (std::size_t k = 0; k < model.segments.size(); ++k)
    if (model.segments[k].end > model.segments[k].start) motions.emplace_back(model.segments[k].start, k + 1);
  return motions;
}

}  // namespace

bool timelineHasSegments(const RollingModel& model) { return !motionStarts(model).empty(); }

bool timelineHasSurfaces(const RollingModel& model) { return model.surfaces.size() > 1; }

spin::SolveStats sampleTimeline(const RollingModel& model, const SolverChoice& choice,
                                const spin::SampleArcLengths& sampleS, const TimelineRowSink& rowSink,
                                const std::string& where) {
  // A storyboard adds the number of the segment each row is in (from 1).
  const std::vector<std::pair<double, std::size_t>> motions = motionStarts(model);
  const double R = model.ballRadius;
  TimelineRow row;
  auto sink = [&](std::size_t index, double s, const spin::Su2& q) {
    const geometry::DarbouxSample f = model.path->at(s);
    const geometry::Vec3 c = f.centre(R), b = spin::fieldB(f, R);
    row.values = {s,
                  f.point.x(),
                  f.point.y(),
                  f.point.z(),
                  f.normal.x(),
                  f.normal.y(),
                  f.normal.z(),
                  c.x(),
                  c.y(),
                  c.z(),
                  q.w,
                  q.x,
                  q.y,
                  q.z,
                  b.x(),
                  b.y(),
                  b.z(),
                  f.tangent.x(),
                  f.tangent.y(),
                  f.tangent.z(),
                  f.normalCurvature,
                  f.geodesicCurvature,
                  f.geodesicTorsion};
    if (!motions.empty()) {
      // The motion that starts last at or before s: a join's row belongs to the segment starting there.
      const auto it =
          std::upper_bound(motions.begin(), motions.end(), s, [](double x, const auto& m) { return x < m.first; });
      row.segment = (it == motions.begin() ? motions.front() : *(it - 1)).second;
      row.surface = model.segments[row.segment - 1].surface;
    }
    rowSink(index, row);
  };
  const spin::Propagator propagator(*model.path, R, choice.method, choice.steps, choice.tolerance);
  const spin::SolveStats stats = propagator.run(sampleS, sink);
  if (stats.status != spin::SolveStatus::Ok)
    throw runtimeError(SourceLoc{where}, "solver failed: {}; nothing written", spin::statusMessage(stats.status));
  return stats;
}

}  // namespace rollspin::jobs
