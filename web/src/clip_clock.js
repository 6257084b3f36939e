// The clip's clock (the MP4's timing: motion::FrameClock, embedded by
// src/jobs/viewer_timeline.cpp as pieces in the clip's seconds): piece k runs
// from seconds[k] to seconds[k + 1] and shows
//   s(t) = s0[k] + (s1[k] − s0[k]) · ease(x),  x = (t − seconds[k]) / (seconds[k + 1] − seconds[k])
// with ease(x) = x, or 3x² − 2x³ when smooth; a hold where s0 = s1. The
// player advances t at the clip's pace (holds included) and shows s(t).

function ease(smooth, x) {
  x = Math.min(1, Math.max(0, x));
  return smooth ? x * x * (3 - 2 * x) : x;
}

// x in [0, 1] with ease(x) = y (ease is increasing): bisection to double precision.
function inverseEase(smooth, y) {
  if (!smooth) return Math.min(1, Math.max(0, y));
  let lo = 0, hi = 1;
  for (let i = 0; i < 60; ++i) {
    const mid = 0.5 * (lo + hi);
    if (ease(true, mid) < y) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

export class ClipClock {
  constructor(data) {
    this.seconds = data.seconds;
    this.s0 = data.s0;
    this.s1 = data.s1;
    this.smooth = data.smooth;
    this.segments = data.segment ?? [];  // the scene segment each piece shows (a hold: its own)
    this.duration = this.seconds[this.seconds.length - 1];
  }

  // The piece holding t (the last one starting at or before t).
  piece(t) {
    let k = 0;
    while (k + 1 < this.s0.length && this.seconds[k + 1] <= t) ++k;
    return k;
  }

  // s at the clip's second t (clamped to the clip).
  sAt(t) {
    t = Math.min(this.duration, Math.max(0, Number(t)));
    const k = this.piece(t), t0 = this.seconds[k], t1 = this.seconds[k + 1];
    if (!(this.s1[k] > this.s0[k])) return this.s0[k];
    return this.s0[k] + (this.s1[k] - this.s0[k]) * ease(this.smooth, (t - t0) / (t1 - t0));
  }

  // The scene segment the clip shows at second t (a hold's own, where s
  // alone would name the motion before it); null without pieces' segments.
  segmentAt(t) {
    return this.segments.length ? this.segments[this.piece(Math.min(this.duration, Math.max(0, Number(t))))] : null;
  }

  // The clip's second where a motion shows s (its start when s begins one,
  // so that playing from a chapter start does not first sit through the
  // hold before it); the end of the clip past the last motion.
  timeAt(s) {
    for (let k = 0; k < this.s0.length; ++k) {
      const s0 = this.s0[k], s1 = this.s1[k];
      if (s1 > s0 && s >= s0 && s < s1) {
        const x = inverseEase(this.smooth, (s - s0) / (s1 - s0));
        return this.seconds[k] + x * (this.seconds[k + 1] - this.seconds[k]);
      }
    }
    return s <= 0 ? 0 : this.duration;
  }
}
