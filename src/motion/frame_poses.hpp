// FramePoseStream — every pose of an animation from ONE forward march of the
// propagator (dense output): the march's sample list is the clip's frame arc
// lengths s_k (non-decreasing in k; a hold repeats s and is emitted once)
// merged with the fixed trail grid g_i (draw_scene.hpp), generated on the fly,
// so memory does not grow with the clip. The march reaches each sample by one
// partial step from the preceding grid node and a sample never feeds back
// into it, so U(s) does not depend on which other samples are asked for: a
// frame's poses are bit for bit those of solveFrame(s), and frames A..B of a
// partial render equal the same frames of a full one. The strobe positions
// (all of [0, L], needed by the first frame already) come from one short
// march before it. The march runs on its own thread, a frame or two ahead of
// the renderer (a bounded queue), and stops once the last frame is out.
#pragma once

#include <atomic>
#include <exception>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include "core/bounded_queue.hpp"
#include "model/rolling_model.hpp"
#include "motion/frame_clock.hpp"
#include "motion/frame_sampling.hpp"
#include "scene/scene_spec.hpp"
#include "spin/propagator.hpp"

namespace rollspin::motion {

// Runs the scene's solver (method, steps, tolerance) once over `samples`;
// throws Runtime (at solver.method) when it fails.
void marchScene(const scene::SceneSpec& spec, const RollingModel& model, const spin::SampleArcLengths& samples,
                const spin::SampleSink& sink);

class FramePoseStream {
 public:
  // Poses of frames range.first … range.last of the clip, one per distinct
  // arc length, in order. Starts the march.
  FramePoseStream(const scene::SceneSpec& spec, const RollingModel& model, const FrameClock& clock, FrameRange range);
  ~FramePoseStream();  // stops the march
  FramePoseStream(const FramePoseStream&) = delete;
  FramePoseStream& operator=(const FramePoseStream&) = delete;

  // The pose for the next distinct arc length (its current.s is that s);
  // nullopt after the last. Rethrows the march's error.
  [[nodiscard]] std::optional<FrameOrientations> next();
  // Seconds next() spent waiting for the march.
  [[nodiscard]] double waitSeconds() const { return queue_.consumerWaitSeconds(); }

 private:
  void march(const std::vector<OrientedSample>& strobe, const std::vector<OrientedSample>& cuts);

  const scene::SceneSpec& spec_;
  const RollingModel& model_;
  const FrameClock& clock_;
  FrameRange range_;
  BoundedQueue<FrameOrientations> queue_{2};
  std::exception_ptr error_;
  std::atomic<bool> stop_{false};  // the renderer has gone: stop at the next sample
  std::thread thread_;
};

}  // namespace rollspin::motion
