#include "jobs/scene_print.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "model/rolling_model.hpp"
#include "motion/frame_clock.hpp"
#include "motion/solve_job.hpp"
#include "scene/scene_writer.hpp"

namespace rollspin::jobs {

using namespace rollspin::model;
using namespace rollspin::motion;

// The resolved scene, with what the engine derives noted beside the keys.
std::string resolvedSceneText(const std::string& sourceName, const scene::SceneSpec& spec) {
  const RollingModel model = buildSceneModel(spec);
  const SolverChoice choice = chooseSolver(spec, model);
  std::map<std::string, std::string> notes;
  if (choice.method != spin::Method::Exact && choice.automaticSteps)
    notes["solver.steps"] = fmt::format("automatic: {} steps", choice.steps);
  if (!spec.timeline.samples)
    notes["timeline.samples"] = fmt::format("{} (60 per turn + 1)", defaultSampleCount(model));
  if (spec.isStoryboard()) {
    // What each segment will do: where on the path, for how long.
    const FrameClock clock(model.segments, spec);
    const std::vector<double> seconds = FrameClock::segmentSeconds(model.segments, spec);
    const double fps = spec.animation.fps.value();
    long long segmentFrames = 0;
    for (std::size_t k = 0; k < spec.segments.size(); ++k) {
      const SegmentSpan& span = model.segments[k];
      // Beside the segment's own duration/speed key (or in place of it, as a
      // comment): how long this segment really lasts, so that no duration
      // printed in a storyboard reads as the clip's.
      const scene::SegmentSpec& segment = spec.segments[k];
      const long long frames = std::llround((segment.path ? seconds[k] : segment.hold) * fps);
      segmentFrames += frames;
      if (segment.path) {
        const std::string range = fmt::format("s {:.6g} to {:.6g}", span.start, span.end);
        const bool own = segment.duration || segment.speed;
        notes[scene::SceneSpec::segmentKey(k) + (!segment.duration && segment.speed ? ".speed" : ".duration")] =
            own ? fmt::format("this segment lasts {:.6g} s ({}), not the clip", seconds[k], range)
                : fmt::format("{:.6g} s: this segment ({}) at the storyboard's speed (see [animation])", seconds[k],
                              range);
      }
      notes[scene::SceneSpec::segmentKey(k)] =
          spec.segments[k].path ? fmt::format("segment {}: s {:.6g} to {:.6g} (length {:.6g}) in {:.6g} s, {} frames",
                                              k + 1, span.start, span.end, span.end - span.start, seconds[k], frames)
                                : fmt::format("segment {}: rests at s = {:.6g} for {:.6g} s, {} frames", k + 1,
                                              span.start, spec.segments[k].hold, frames);
      if (model.surfaces.size() > 1)
        notes[scene::SceneSpec::segmentKey(k)] +=
            fmt::format(", on surface {} (a {})", span.surface, scene::toString(spec.surfaceOf(k).kind));
    }
    // The clip's frames are the segments' and the holds at its ends (the
    // opening one at least one frame: the start), said so that the sum of
    // the segments' counts above never reads as a miscount.
    const double clipSeconds = static_cast<double>(clock.frameCount()) / fps;
    const long long closing = clock.holdFrames(), opening = clock.frameCount() - segmentFrames - closing;
    notes[spec.animation.speed ? "animation.speed" : "animation.duration"] = fmt::format(
        "{}segments without their own timing move at {:.6g} per second; the clip lasts {:.6g} s, {} frames ({} "
        "opening, {} in the segments, {} closing)",
        spec.animation.speed ? "" : "the whole path's time at one speed, not the clip's: ",
        spec.animation.speed ? *spec.animation.speed : model.path->length() / spec.animation.duration, clipSeconds,
        clock.frameCount(), opening, segmentFrames, closing);
  }
  if (model.plate)
    notes["plate.radius"] =
        fmt::format("the contact circle's radius is derived: R1/{} = {}", model.plate->contactSpeedRatio,
                    model.plate->radius / model.plate->contactSpeedRatio);
  return fmt::format("# {} resolved: every default filled in, extends and --set applied.\n# path: {}, length {}\n\n{}",
                     sourceName, model.path->describe(), model.path->length(), scene::writeScene(spec, notes));
}

}  // namespace rollspin::jobs
