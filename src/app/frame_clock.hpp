// FrameClock — an animation's frame index → arc length, exactly:
//   frames 0 … H−1          hold at s = 0
//   frames H … H+N−1        s_k = L · ease(j / (N − 1)),  j = k − H
//   frames H+N … H+N+H−1    hold at s = L
// with N = round(T · fps) motion frames (T = animation.duration, or L/speed),
// H = round(hold · fps) (fps the exact rational, e.g. 30000/1001), ease(x) = x (linear) or 3x² − 2x³ (smooth: starts
// and stops at rest). The motion therefore lasts exactly N/fps = T seconds of
// video and the clip has N + 2H frames. s_k depends on k alone, so any subset
// of frames (`--frames A:B`) shows the same poses as the full clip.
#pragma once

#include <string>

#include "scene/scene_spec.hpp"

namespace rollspin::app {

[[nodiscard]] double ease(scene::Easing easing, double x);

class FrameClock {
 public:
  // Throws BadInput (at the animation key) when the clip would have fewer
  // than 2 motion frames or more than kMaxFrames frames.
  FrameClock(double pathLength, const scene::SceneSpec& spec);

  static constexpr long long kMaxFrames = 10'000'000;

  [[nodiscard]] long long frameCount() const { return motionFrames_ + 2 * holdFrames_; }
  [[nodiscard]] long long motionFrames() const { return motionFrames_; }
  [[nodiscard]] long long holdFrames() const { return holdFrames_; }
  [[nodiscard]] const scene::FrameRate& fps() const { return fps_; }
  // Arc length shown by frame k (0 ≤ k < frameCount), non-decreasing in k.
  [[nodiscard]] double arcLength(long long frame) const;

 private:
  double length_;
  scene::FrameRate fps_;
  long long motionFrames_;
  long long holdFrames_;
  scene::Easing easing_;
};

// `--frames A:B` (inclusive, 0-based) → [first, last]; throws BadInput naming
// the argument and the clip's frame count when malformed or out of range.
struct FrameRange {
  long long first = 0, last = 0;
  [[nodiscard]] long long count() const { return last - first + 1; }
};
[[nodiscard]] FrameRange parseFrameRange(const std::string& text, long long frameCount);

}  // namespace rollspin::app
