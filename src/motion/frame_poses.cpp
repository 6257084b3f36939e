#include "motion/frame_poses.hpp"

#include <pthread.h>

#include <algorithm>

#include "core/error.hpp"
#include "core/stage_log.hpp"
#include "motion/solve_job.hpp"

namespace rollspin::motion {

namespace {

// Thrown by the march's sink to end the march early: once the last frame is
// out, or when the renderer has gone (the queue was aborted). The propagator
// holds no resources beyond RAII locals, so unwinding through it is clean.
struct MarchStopped {};

// The march's samples: trail grid points g_0 … g_{gridCount−1} merged with
// the range's distinct frame arc lengths; on a tie the grid point comes
// first. A forward-only cursor: the propagator asks for j in non-decreasing
// order (SampleArcLengths::generated), and its sink is called for the
// sample last asked for, so atFrame() says what that sample is.
class MergedSamples {
 public:
  MergedSamples(const TrailGrid& grid, const FrameClock& clock, FrameRange range)
      : grid_(grid), clock_(clock), range_(range), k_(range.first) {
    for (long long k = range.first; k <= range.last; ++k)
      if (k == range.first || clock.arcLength(k) != clock.arcLength(k - 1)) ++frames_;
    // The trails need the grid below the last frame's s, and g_0 always.
    const double lastS = clock.arcLength(range.last);
    if (grid.count > 0) {
      gridCount_ = 1;
      while (gridCount_ < grid.count && grid.at(gridCount_) < lastS) ++gridCount_;
    }
  }

  [[nodiscard]] std::size_t size() const { return gridCount_ + frames_; }
  [[nodiscard]] std::size_t frames() const { return frames_; }
  [[nodiscard]] double at(std::size_t j) {
    while (consumed_ <= j) advance();
    return value_;
  }
  [[nodiscard]] bool atFrame() const { return isFrame_; }

 private:
  void advance() {
    const bool gridLeft = gi_ < gridCount_;
    if (gridLeft && (k_ > range_.last || grid_.at(gi_) <= clock_.arcLength(k_))) {
      value_ = grid_.at(gi_++);
      isFrame_ = false;
    } else {
      value_ = clock_.arcLength(k_);
      isFrame_ = true;
      do ++k_;  // a hold repeats the pose: one sample for the run of equal s
      while (k_ <= range_.last && clock_.arcLength(k_) == value_);
    }
    ++consumed_;
  }

  TrailGrid grid_;
  const FrameClock& clock_;
  FrameRange range_;
  std::size_t gridCount_ = 0, frames_ = 0;
  std::size_t gi_ = 0, consumed_ = 0;
  long long k_;
  double value_ = 0.0;
  bool isFrame_ = false;
};

}  // namespace

void marchScene(const scene::SceneSpec& spec, const RollingModel& model, const spin::SampleArcLengths& samples,
                const spin::SampleSink& sink) {
  const SolverChoice choice = chooseSolver(spec, model);
  const spin::Propagator propagator(*model.path, model.ballRadius, choice.method, choice.steps, choice.tolerance);
  const spin::SolveStats stats = propagator.run(samples, sink);
  if (stats.status != spin::SolveStatus::Ok)
    throw runtimeError(spec.where("solver.method"), "solver failed: {}", spin::statusMessage(stats.status));
}

FramePoseStream::FramePoseStream(const scene::SceneSpec& spec, const RollingModel& model, const FrameClock& clock,
                                 FrameRange range)
    : spec_(spec), model_(model), clock_(clock), range_(range) {
  // The stage log is not thread-safe: record here what the march will do.
  StageLog::instance().record("solver");
  if (spec.render.trails) StageLog::instance().record("trails");
  std::vector<double> strobeS = strobeArcLengths(spec, model);  // records "strobe"
  const std::size_t strobeCount = strobeS.size();
  // The surface changes' poses come from the same short march (sorted after the strobe's).
  for (double s : cutArcLengths(model)) strobeS.push_back(s);
  std::sort(strobeS.begin() + static_cast<std::ptrdiff_t>(strobeCount), strobeS.end());
  (void)chooseSolver(spec, model);  // bad input surfaces here, on the caller's thread
  thread_ = std::thread([this, strobeS = std::move(strobeS), strobeCount] {
    pthread_setname_np(pthread_self(), "rollspin-poses");
    try {
      std::vector<OrientedSample> early(strobeS.size());
      if (!strobeS.empty()) {
        // One non-decreasing list for the march; each sample back to its place.
        std::vector<std::size_t> order(strobeS.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return strobeS[a] < strobeS[b]; });
        std::vector<double> sorted;
        for (std::size_t i : order) sorted.push_back(strobeS[i]);
        marchScene(spec_, model_, sorted, [&](std::size_t i, double s, const spin::Su2& q) {
          early[order[i]] = {s, q};
        });
      }
      const auto split = early.begin() + static_cast<std::ptrdiff_t>(strobeCount);
      march({early.begin(), split}, {split, early.end()});
    } catch (const MarchStopped&) {
    } catch (...) {
      error_ = std::current_exception();
    }
    queue_.close();  // after error_ is set: next() reads it once the queue says so
  });
}

FramePoseStream::~FramePoseStream() {
  stop_ = true;    // a march between two frames stops at its next sample
  queue_.abort();  // one blocked on a full queue, at once
  thread_.join();
}

void FramePoseStream::march(const std::vector<OrientedSample>& strobe, const std::vector<OrientedSample>& cuts) {
  const TrailGrid grid = trailGrid(spec_, model_);
  MergedSamples samples(grid, clock_, range_);
  std::vector<OrientedSample> trail;  // the grid so far: every trail is a prefix of it
  std::size_t emitted = 0;
  const auto sink = [&](std::size_t, double s, const spin::Su2& q) {
    if (stop_) throw MarchStopped{};
    if (!samples.atFrame()) {
      trail.push_back({s, q});
      return;
    }
    // Trail of the frame at s: {g_i < s} ∪ {s}, g_0 always (as frameSampling).
    std::size_t n = trail.size();
    while (n > 1 && trail[n - 1].s >= s) --n;
    FrameOrientations frame;
    frame.current = {s, q};
    if (grid.count > 0) {
      frame.trail.assign(trail.begin(), trail.begin() + static_cast<std::ptrdiff_t>(n));
      frame.trail.push_back(frame.current);
    }
    frame.strobe = strobe;
    frame.cuts = cuts;
    if (!queue_.push(std::move(frame))) throw MarchStopped{};
    if (++emitted == samples.frames()) throw MarchStopped{};  // the rest of the path is not needed
  };
  marchScene(spec_, model_,
             spin::SampleArcLengths::generated(samples.size(), [&](std::size_t j) { return samples.at(j); }), sink);
}

std::optional<FrameOrientations> FramePoseStream::next() {
  std::optional<FrameOrientations> frame = queue_.pop();
  if (!frame && error_) std::rethrow_exception(error_);
  return frame;
}

}  // namespace rollspin::motion
