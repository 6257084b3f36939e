#include "motion/frame_clock.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace rollspin::motion {

double ease(scene::Easing easing, double x) {
  x = std::clamp(x, 0.0, 1.0);
  return easing == scene::Easing::Linear ? x : x * x * (3.0 - 2.0 * x);
}

FrameClock::FrameClock(double pathLength, const scene::SceneSpec& spec)
    : length_(pathLength), fps_(spec.animation.fps), easing_(spec.animation.easing) {
  const scene::AnimationSpec& a = spec.animation;
  const std::string timeKey = a.speed ? "animation.speed" : "animation.duration";
  const double seconds = a.speed ? pathLength / *a.speed : a.duration;
  // Frames = seconds · num / den, rounded: 10 s at 30000/1001 is 300 frames
  // (299.7 rounded), lasting 10.01 s.
  const double rate = double(fps_.num) / double(fps_.den);
  const double motion = std::round(seconds * rate);
  const double hold = std::round(a.hold * rate);
  if (!(motion >= 2.0))
    throw badInput(spec.where(timeKey), "{}: {:.6g} s at {} fps is {} frame(s); an animation needs at least 2", timeKey,
                   seconds, fps_.describe(), motion);
  if (motion + 2.0 * hold > double(kMaxFrames))
    throw badInput(spec.where(motion > double(kMaxFrames) / 2 ? timeKey : "animation.hold"),
                   "the clip would have {:.0f} frames ({:.6g} s of motion, {:.6g} s holds at {} fps); the limit is {}",
                   motion + 2.0 * hold, seconds, a.hold, fps_.describe(), kMaxFrames);
  motionFrames_ = static_cast<long long>(motion);
  holdFrames_ = static_cast<long long>(hold);
  frameCount_ = motionFrames_ + 2 * holdFrames_;
}

std::vector<double> FrameClock::segmentSeconds(std::span<const SegmentSpan> spans, const scene::SceneSpec& spec) {
  const double total = spans.empty() ? 0.0 : spans.back().end;
  std::vector<double> seconds;
  for (std::size_t k = 0; k < spec.segments.size(); ++k) {
    const scene::SegmentSpec& seg = spec.segments[k];
    const double L = spans[k].end - spans[k].start;
    if (!seg.path) seconds.push_back(0.0);
    else if (seg.duration) seconds.push_back(*seg.duration);
    else if (seg.speed) seconds.push_back(L / *seg.speed);
    else if (spec.animation.speed) seconds.push_back(L / *spec.animation.speed);
    else seconds.push_back(spec.animation.duration * L / total);
  }
  return seconds;
}

FrameClock::FrameClock(std::span<const SegmentSpan> spans, const scene::SceneSpec& spec)
    : length_(0.0), fps_(spec.animation.fps), motionFrames_(0), holdFrames_(0), easing_(spec.animation.easing) {
  const double fps = fps_.value();
  const double hold = std::round(spec.animation.hold * fps);
  const std::vector<double> seconds = segmentSeconds(spans, spec);
  double frames = std::max(hold, 1.0);
  long long lastFirst = 0, lastFrames = 0;
  std::vector<Stage> stages{{0, static_cast<long long>(frames), 0, 0, 0, 0.0, 0.0, false}};
  for (std::size_t k = 0; k < spec.segments.size(); ++k) {
    const scene::SegmentSpec& seg = spec.segments[k];
    const std::string key = scene::SceneSpec::segmentKey(k);
    const double n = std::round((seg.path ? seconds[k] : seg.hold) * fps);
    if (seg.path && !(n >= 1.0)) {
      const std::string timeKey = seg.duration ? key + ".duration"
                                  : seg.speed  ? key + ".speed"
                                               : (spec.animation.speed ? "animation.speed" : "animation.duration");
      throw badInput(spec.where(timeKey), "{}: the motion of {} lasts {:.6g} s, less than one frame at {} fps", timeKey,
                     key, seconds[k], fps_.describe());
    }
    if (frames + n + hold > double(kMaxFrames))
      throw badInput(spec.where(key), "{}: the storyboard would have more than {} frames at {} fps", key, kMaxFrames,
                     fps_.describe());
    const auto first = static_cast<long long>(frames);
    // Segment 1's time runs from the clip's first frame (the opening hold shows it).
    const long long segmentFirst = k == 0 ? 0 : first;
    if (n >= 1.0)
      stages.push_back({first, static_cast<long long>(n), k, segmentFirst, static_cast<long long>(n), spans[k].start,
                        spans[k].end, seg.path.has_value()});
    if (k + 1 == spec.segments.size()) {
      lastFirst = segmentFirst;
      lastFrames = static_cast<long long>(n);
    }
    frames += n;
    if (seg.path) motionFrames_ += static_cast<long long>(n);
  }
  const double s = spans.empty() ? 0.0 : spans.back().end;
  length_ = s;
  holdFrames_ = static_cast<long long>(hold);
  // The closing hold belongs to the last segment: its time keeps running.
  stages.push_back(
      {static_cast<long long>(frames), holdFrames_, spec.segments.size() - 1, lastFirst, lastFrames, s, s, false});
  frameCount_ = static_cast<long long>(frames) + holdFrames_;
  stages_ = std::move(stages);
}

const FrameClock::Stage& FrameClock::stageAt(long long frame) const {
  // The last stage whose first frame is ≤ frame (empty stages never win: a
  // later stage with the same first frame follows them).
  const auto it = std::upper_bound(stages_.begin(), stages_.end(), frame,
                                   [](long long f, const Stage& st) { return f < st.first; });
  return *(it == stages_.begin() ? it : it - 1);
}

StoryPlace FrameClock::place(long long frame) const {
  // Frame k starts k · den / num seconds into the clip (exact rationals).
  auto seconds = [this](long long frames) { return double(frames) * double(fps_.den) / double(fps_.num); };
  if (stages_.empty()) return {0, seconds(frame), seconds(frameCount_)};
  const Stage& st = stageAt(frame);
  return {st.segment, std::max(0.0, seconds(frame - st.segmentFirst)), seconds(st.segmentFrames)};
}

double FrameClock::arcLength(long long frame) const {
  if (!stages_.empty()) {
    const Stage& st = stageAt(frame);
    if (!st.motion) return st.s0;
    const long long j = frame - st.first + 1;  // 1 … N
    if (j >= st.frames) return st.s1;          // exactly the segment's end
    return std::min(st.s1, st.s0 + (st.s1 - st.s0) * ease(easing_, double(j) / double(st.frames)));
  }
  const long long j = frame - holdFrames_;
  if (j <= 0) return 0.0;
  if (j >= motionFrames_ - 1) return length_;
  // Exact ends (0 and L) above; in between the eased fraction of the path.
  return std::min(length_, length_ * ease(easing_, double(j) / double(motionFrames_ - 1)));
}

double FrameClock::arcLengthAt(double frame) const {
  if (!stages_.empty()) {
    // The last motion that has begun by `frame` (its j = 0 is the frame
    // before its first): between motions the ball rests at that one's end.
    double s = 0.0;
    for (const Stage& st : stages_) {
      if (!st.motion) {
        if (double(st.first) <= frame) s = st.s0;
        continue;
      }
      const double j = frame - double(st.first) + 1.0;  // 0 … N
      if (j <= 0.0) break;
      if (j >= double(st.frames)) {
        s = st.s1;
        continue;
      }
      return std::min(st.s1, st.s0 + (st.s1 - st.s0) * ease(easing_, j / double(st.frames)));
    }
    return s;
  }
  const double j = frame - double(holdFrames_);
  if (j <= 0.0) return 0.0;
  if (j >= double(motionFrames_ - 1)) return length_;
  return std::min(length_, length_ * ease(easing_, j / double(motionFrames_ - 1)));
}

std::vector<double> FrameClock::motionBounds() const {
  std::vector<double> bounds{0.0, double(frameCount_ - 1)};
  if (stages_.empty()) {
    bounds.push_back(double(holdFrames_));
    bounds.push_back(double(holdFrames_ + motionFrames_ - 1));
  }
  for (const Stage& st : stages_)
    if (st.motion) {
      bounds.push_back(double(st.first) - 1.0);
      bounds.push_back(double(st.first + st.frames) - 1.0);
    }
  for (double& b : bounds) b = std::clamp(b, 0.0, double(frameCount_ - 1));
  std::sort(bounds.begin(), bounds.end());
  bounds.erase(std::unique(bounds.begin(), bounds.end()), bounds.end());
  return bounds;
}

FrameRange parseFrameRange(const std::string& text, long long frameCount) {
  const SourceLoc loc{"--frames " + text};
  const auto colon = text.find(':');
  auto parse = [&](const std::string& part, long long& out) {
    const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), out);
    return !part.empty() && ec == std::errc() && ptr == part.data() + part.size();
  };
  FrameRange r;
  if (colon == std::string::npos || !parse(text.substr(0, colon), r.first) || !parse(text.substr(colon + 1), r.last))
    throw badInput(loc, "expected --frames FIRST:LAST (0-based, inclusive, e.g. --frames 10:19)");
  if (r.first < 0 || r.last < r.first || r.last >= frameCount)
    throw badInput(loc, "expected 0 <= FIRST <= LAST <= {} (this clip has {} frames)", frameCount - 1, frameCount);
  return r;
}

}  // namespace rollspin::motion
