// Holds playback at 30 frames a second where the renderer cannot draw every
// pixel that fast (a software renderer such as SwiftShader, a weak laptop):
// while playing, the views render at a lower pixel ratio (down to
// MIN_SCALE of the device's, on each axis) when frames come slower than 30
// a second, and higher again when they come well faster; once playback
// stops, the frame is drawn again at full resolution. The canvases keep
// their size on the page.
const TARGET_MS = 1000 / 30;
const MIN_SCALE = 0.5;
const STEP = 0.1;
const SETTLE_MS = 400;  // frames at one scale before the next step
// Lower the scale when frames come slower than 29.4 a second (a mean
// frame of two 60 Hz refreshes, 33.3 ms, stays), raise it only when they
// come faster than 37.5: between the two the scale stays (no hunting).
const SLOWER_THAN = 1.02 * TARGET_MS;
const FASTER_THAN = 0.8 * TARGET_MS;

export class FramePacer {
  constructor(twin) {
    this.twin = twin;
    this.last = null;
    this.mean = 0;
    this.changed = 0;
    this.playingScale = 1;  // where the last playback settled: the next starts there
    this.enabled = true;    // false: every frame at full resolution (window.rollspin.adaptiveResolution)
  }

  // After a frame drawn at `now` (requestAnimationFrame's clock, ms);
  // returns true where the views must be drawn again (back at full scale).
  drawn(now, playing) {
    if (!playing || !this.enabled) {
      this.last = null;
      this.mean = 0;
      if (this.twin.renderScale === 1) return false;
      if (this.enabled) this.playingScale = this.twin.renderScale;
      this.twin.setRenderScale(1);
      return true;
    }
    // (The first frames after play starts are slow anyway: a settle first.)
    if (this.last === null) {
      if (this.twin.renderScale !== this.playingScale) this.twin.setRenderScale(this.playingScale);
      this.changed = now;
    }
    if (this.last !== null) this.mean = this.mean ? 0.8 * this.mean + 0.2 * (now - this.last) : now - this.last;
    this.last = now;
    if (!this.mean || now - this.changed < SETTLE_MS) return false;
    const scale = this.twin.renderScale;
    let next = scale;
    if (this.mean > SLOWER_THAN) next = Math.max(MIN_SCALE, scale - STEP);
    else if (this.mean < FASTER_THAN) next = Math.min(1, scale + STEP);
    if (next !== scale) {
      this.twin.setRenderScale(Math.round(next * 100) / 100);
      this.changed = now;
      this.mean = 0;
    }
    return false;
  }
}
