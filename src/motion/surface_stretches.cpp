#include "motion/surface_stretches.hpp"

#include "motion/frame_clock.hpp"

namespace rollspin::motion {

namespace {

// Segments [first, end) as a storyboard on their surface. Each motion keeps
// the seconds the whole clip gives it (a share of animation.duration would
// otherwise be a share of the stretch), so the stretch's camera moves keep
// the clip's times.
scene::SceneSpec stretchScene(const scene::SceneSpec& spec, const std::vector<double>& seconds, std::size_t first,
                              std::size_t end) {
  scene::SceneSpec sub = spec;
  sub.surface = spec.surfaceOf(end - 1);
  sub.segments.assign(spec.segments.begin() + static_cast<std::ptrdiff_t>(first),
                      spec.segments.begin() + static_cast<std::ptrdiff_t>(end));
  for (std::size_t k = 0; k < sub.segments.size(); ++k) {
    scene::SegmentSpec& seg = sub.segments[k];
    seg.surface.reset();
    if (seg.path) {
      seg.duration = seconds[first + k];
      seg.speed.reset();
    }
  }
  return sub;
}

}  // namespace

std::vector<SurfaceStretch> surfaceStretches(const scene::SceneSpec& spec, const model::RollingModel& model) {
  std::vector<SurfaceStretch> out;
  if (model.surfaces.size() < 2) return out;
  const std::vector<double> seconds = FrameClock::segmentSeconds(model.segments, spec);
  // Where each stretch begins: segment 0 and every later motion with its own
  // surface, unless the stretch so far has no motion (it joins the next).
  std::vector<std::size_t> firsts{0};
  bool moved = false;
  for (std::size_t k = 0; k < spec.segments.size(); ++k) {
    const bool motion = spec.segments[k].path.has_value();
    if (k > 0 && motion && spec.segments[k].surface && moved) firsts.push_back(k);
    moved = moved || motion;
  }
  for (std::size_t i = 0; i < firsts.size(); ++i) {
    SurfaceStretch stretch;
    stretch.firstSegment = firsts[i];
    stretch.endSegment = i + 1 < firsts.size() ? firsts[i + 1] : spec.segments.size();
    stretch.start = model.segments[stretch.firstSegment].start;
    stretch.end = model.segments[stretch.endSegment - 1].end;
    stretch.spec = stretchScene(spec, seconds, stretch.firstSegment, stretch.endSegment);
    stretch.model = model::buildModel(stretch.spec);
    out.push_back(std::move(stretch));
  }
  return out;
}

}  // namespace rollspin::motion
