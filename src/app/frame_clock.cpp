#include "app/frame_clock.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace rollspin::app {

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
    throw badInput(spec.where(timeKey), "{}: {:.6g} s at {} fps is {} frame(s); an animation needs at least 2",
                   timeKey, seconds, fps_.describe(), motion);
  if (motion + 2.0 * hold > double(kMaxFrames))
    throw badInput(spec.where(motion > double(kMaxFrames) / 2 ? timeKey : "animation.hold"),
                   "the clip would have {:.0f} frames ({:.6g} s of motion, {:.6g} s holds at {} fps); the limit is {}",
                   motion + 2.0 * hold, seconds, a.hold, fps_.describe(), kMaxFrames);
  motionFrames_ = static_cast<long long>(motion);
  holdFrames_ = static_cast<long long>(hold);
}

double FrameClock::arcLength(long long frame) const {
  const long long j = frame - holdFrames_;
  if (j <= 0) return 0.0;
  if (j >= motionFrames_ - 1) return length_;
  // Exact ends (0 and L) above; in between the eased fraction of the path.
  return std::min(length_, length_ * ease(easing_, double(j) / double(motionFrames_ - 1)));
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

}  // namespace rollspin::app
