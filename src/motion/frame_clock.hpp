// FrameClock — an animation's frame index → arc length, exactly:
//   frames 0 … H−1          hold at s = 0
//   frames H … H+N−1        s_k = L · ease(j / (N − 1)),  j = k − H
//   frames H+N … H+N+H−1    hold at s = L
// with N = round(T · fps) motion frames (T = animation.duration, or L/speed),
// H = round(hold · fps) (fps the exact rational, e.g. 30000/1001), ease(x) = x (linear) or 3x² − 2x³ (smooth: starts
// and stops at rest). The motion therefore lasts exactly N/fps = T seconds of
// video and the clip has N + 2H frames. s_k depends on k alone, so any subset
// of frames (`--frames A:B`) shows the same poses as the full clip.
//
// A storyboard (scene [[segment]] entries) plays its segments in order:
//   frames 0 … H'−1          hold at s = 0, H' = max(H, 1) (the clip opens
//                            on the start pose)
//   a motion k               N_k = round(T_k · fps) frames showing
//                            s = s_k + L_k · ease(j / N_k), j = 1 … N_k
//                            (its start is the pose before it; its last frame
//                            is exactly s_k + L_k); T_k = the segment's
//                            duration, or L_k / its speed, or L_k /
//                            animation.speed, or its share of
//                            animation.duration by length
//   a hold k                 round(hold_k · fps) frames at its point
//   the last H frames        hold at s = L
// so the clip has H' + Σ N_k + Σ round(hold_k · fps) + H frames, and each
// motion eases in and out on its own (the ball rests at every join).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "model/rolling_model.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::motion {

using model::RollingModel;
using model::SegmentSpan;

[[nodiscard]] double ease(scene::Easing easing, double x);

// Which storyboard segment a frame belongs to, and the seconds since that
// segment began (0 during the opening hold; the closing hold belongs to the
// last segment). A scene without segments is one segment.
struct StoryPlace {
  std::size_t segment = 0;
  double seconds = 1e300;   // a still: long after its segment began
  double duration = 1e300;  // how long the segment plays (its own frames; the opening hold not counted)
};

class FrameClock {
 public:
  // Throws BadInput (at the animation key) when the clip would have fewer
  // than 2 motion frames or more than kMaxFrames frames.
  FrameClock(double pathLength, const scene::SceneSpec& spec);
  // A storyboard: spans[k] = where segment k lies on the whole path (a hold:
  // start = end), one per spec.segments entry; motions show exactly these
  // arc lengths at their ends. Throws BadInput at the segment's timing key
  // when a motion would get no frame, or the clip more than kMaxFrames.
  FrameClock(std::span<const SegmentSpan> spans, const scene::SceneSpec& spec);
  // The seconds of motion T_k of each storyboard segment (0 for a hold).
  [[nodiscard]] static std::vector<double> segmentSeconds(std::span<const SegmentSpan> spans,
                                                          const scene::SceneSpec& spec);

  static constexpr long long kMaxFrames = 10'000'000;

  [[nodiscard]] long long frameCount() const { return frameCount_; }
  [[nodiscard]] StoryPlace place(long long frame) const;
  [[nodiscard]] long long motionFrames() const { return motionFrames_; }
  [[nodiscard]] long long holdFrames() const { return holdFrames_; }
  [[nodiscard]] const scene::FrameRate& fps() const { return fps_; }
  // Arc length shown by frame k (0 ≤ k < frameCount), non-decreasing in k.
  [[nodiscard]] double arcLength(long long frame) const;
  // The same formulas at a fractional frame f ∈ [0, frameCount − 1] (f =
  // seconds · fps): continuous and non-decreasing, equal to arcLength(k) at
  // every whole k. A glTF animation keys the motion at such times.
  [[nodiscard]] double arcLengthAt(double frame) const;
  // The fractional frames where a motion starts or stops (the pieces of
  // arcLengthAt: each motion, each hold), sorted, with 0 and
  // frameCount − 1.
  [[nodiscard]] std::vector<double> motionBounds() const;

 private:
  double length_;
  scene::FrameRate fps_;
  long long motionFrames_;
  long long holdFrames_;
  scene::Easing easing_;
  long long frameCount_ = 0;
  // A storyboard: its stages (opening hold, each segment, closing hold) in
  // order; empty otherwise.
  struct Stage {
    long long first = 0, frames = 0;  // frame range [first, first + frames)
    std::size_t segment = 0;
    long long segmentFirst = 0;   // the segment's own first frame
    long long segmentFrames = 0;  // and how many frames it plays (not counting the clip's holds)
    double s0 = 0.0, s1 = 0.0;    // a motion from s0 to s1; a hold: s0 = s1
    bool motion = false;
  };
  std::vector<Stage> stages_;
  [[nodiscard]] const Stage& stageAt(long long frame) const;
};

// `--frames A:B` (inclusive, 0-based) → [first, last]; throws BadInput naming
// the argument and the clip's frame count when malformed or out of range.
struct FrameRange {
  long long first = 0, last = 0;
  [[nodiscard]] long long count() const { return last - first + 1; }
};
[[nodiscard]] FrameRange parseFrameRange(const std::string& text, long long frameCount);

}  // namespace rollspin::motion
