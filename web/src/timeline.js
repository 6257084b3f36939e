// The solver's timeline at any arc length s, from the knots the C++ side
// embeds (src/jobs/viewer_timeline.hpp): cubic Hermite interpolation with the
// solver's own derivatives, never slerp.
//   dq/ds = −½ (0, B) ⊗ q            (U = qw − i q·σ, dU/ds = −(i/2) ω·σ U, B = −ω)
//   dC/ds = embedded per knot         ((1 − κ_n R) t − R τ_g u)
// The spinor's sign is kept: q and −q are different spinors.

// Half a turn: within this band qw counts as 0, on the positive sheet
// (spin/su2.cpp kHalfTurnBand).
const HALF_TURN_BAND = 1e-12;

// The Hermite basis at t ∈ [0, 1] for an interval of length h: weights of
// (p0, h·m0, p1, h·m1).
function hermiteWeights(t, h) {
  const t2 = t * t, t3 = t2 * t;
  return [2 * t3 - 3 * t2 + 1, (t3 - 2 * t2 + t) * h, -2 * t3 + 3 * t2, (t3 - t2) * h];
}

// dq/ds = −½ (0, b) ⊗ q, Hamilton's product, q = [w, x, y, z].
export function spinorRate(q, b) {
  const [w, x, y, z] = q;
  const [bx, by, bz] = b;
  return [
    0.5 * (bx * x + by * y + bz * z),
    -0.5 * (w * bx + (by * z - bz * y)),
    -0.5 * (w * by + (bz * x - bx * z)),
    -0.5 * (w * bz + (bx * y - by * x)),
  ];
}

// R(q) v for a unit quaternion (normalised here: the interpolant's |q| is 1 to ~1e-9).
export function rotate(q, v) {
  const n = Math.hypot(q[0], q[1], q[2], q[3]);
  const w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
  // v + 2w (u × v) + 2 u × (u × v), u = (x, y, z)
  const cx = y * v[2] - z * v[1], cy = z * v[0] - x * v[2], cz = x * v[1] - y * v[0];
  return [
    v[0] + 2 * (w * cx + y * cz - z * cy),
    v[1] + 2 * (w * cy + z * cx - x * cz),
    v[2] + 2 * (w * cz + x * cy - y * cx),
  ];
}

// The angles the renders print (spin/su2.cpp): the lab rotation angle in
// [0, π] and the spinor angle ψ in [0, 4π), with the sheet.
export function angles(q) {
  const vn = Math.hypot(q[1], q[2], q[3]);
  const rotation = 2 * Math.atan2(vn, Math.abs(q[0]));
  const negative = q[0] < -HALF_TURN_BAND;
  return { rotation, spinor: negative ? rotation + 2 * Math.PI : rotation, negativeSheet: negative };
}

export class Timeline {
  constructor(data) {
    this.length = data.length;
    this.ballRadius = data.ballRadius;
    this.marker = data.marker;
    this.s = Float64Array.from(data.s);
    this.q = Float64Array.from(data.q);
    this.B = Float64Array.from(data.B);
    this.centre = Float64Array.from(data.centre);
    this.centreRate = Float64Array.from(data.centreRate);
    this.chapters = data.chapters;
    // Segments with motion, by start: a join's s belongs to the segment starting there.
    this.motions = data.chapters.filter((c) => c.end > c.start);
  }

  // The interval [s_k, s_k+1] holding s (the last one of positive length at or before s).
  interval(s) {
    const knots = this.s;
    let lo = 0, hi = knots.length - 1;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (knots[mid] <= s) lo = mid;
      else hi = mid;
    }
    return lo;
  }

  vector(array, width, k) {
    return Array.from(array.subarray(width * k, width * k + width));
  }

  // Cubic Hermite on the interval holding s: value(k) is a knot's value, rate(k, value) its derivative d/ds.
  hermite(s, value, rate) {
    const k = this.interval(s);
    const s0 = this.s[k], h = this.s[k + 1] - s0;
    const p0 = value(k), p1 = value(k + 1);
    if (!(h > 0)) return p0;
    const m0 = rate(k, p0), m1 = rate(k + 1, p1);
    const [a, b, c, d] = hermiteWeights((s - s0) / h, h);
    return p0.map((_, i) => a * p0[i] + b * m0[i] + c * p1[i] + d * m1[i]);
  }

  // The spinor q(s) = [qw, qx, qy, qz], with dq/ds from the field.
  quaternion(s) {
    return this.hermite(s, (k) => this.vector(this.q, 4, k), (k, q) => spinorRate(q, this.vector(this.B, 3, k)));
  }

  // The ball's centre C(s).
  ballCentre(s) {
    return this.hermite(s, (k) => this.vector(this.centre, 3, k), (k) => this.vector(this.centreRate, 3, k));
  }

  // The field B(s) (linear between knots: for drawing the arrow only).
  field(s) {
    const k = this.interval(s);
    const s0 = this.s[k], h = this.s[k + 1] - s0;
    const b0 = this.vector(this.B, 3, k), b1 = this.vector(this.B, 3, k + 1);
    const t = h > 0 ? (s - s0) / h : 0;
    return b0.map((v, i) => v + t * (b1[i] - v));
  }

  // The storyboard segment (from 1) whose motion s is in, as `rollspin timeline`'s column; 0 without one.
  segment(s) {
    let number = this.motions.length ? this.motions[0].number : 0;
    for (const m of this.motions) if (m.start <= s) number = m.number;
    return number;
  }

  // Where the ball view looks from at s, [azimuth, elevation] (degrees): the
  // current segment's camera keys over the earlier ones' (null without chapters).
  viewDeg(s) {
    const current = this.segment(s);
    return this.chapters.find((c) => c.number === current)?.viewDeg ?? null;
  }

  // The surface shown at s: the current segment's (0 for GLB node "surface", k for "surface.k").
  surface(s) {
    const current = this.segment(s);
    return this.chapters.find((c) => c.number === current)?.surface ?? 0;
  }

  clamp(s) {
    return Math.min(this.length, Math.max(0, Number(s)));
  }

  // What window.rollspin.state() returns.
  state(s) {
    const quaternion = this.quaternion(s);
    return { s, quaternion, bloch: rotate(quaternion, this.marker), segment: this.segment(s), surface: this.surface(s) };
  }
}
