#version 450 core
// A line's pixel: its coverage by the polyline (the union of its segments'
// capsules) through a one-pixel ramp on the distance from the pixel centre
// (a box filter across a straight edge), as alpha. The scene has one sample
// (see the renderer), so this is the line's antialiasing.
//
// Near a joint two capsules reach the same pixels. Each pixel is drawn by
// the segment nearest to it among the segment and its two neighbours (ties
// go to the earlier one), with the distance to that nearest one: blended
// once, the join is neither a bead nor a notch. The neighbour's distance is
// computed from the same window positions by the same code as in its own
// invocation (`precise`: no reassociation), so the two agree bit for bit.
// A pixel's result depends only on its position: a line drawn under a
// scissor gives the same bytes as drawn whole.
uniform vec4 lineColor;  // linear RGB + alpha
uniform float widthPx;
flat in vec2 segmentStart;
flat in vec2 segmentEnd;
flat in vec2 previousStart;
flat in vec2 nextEnd;
flat in int hasPrevious;
flat in int hasNext;
out vec4 fragColor;
#include "srgb"

// Squared distance from p to the segment a → b. Lengths are measured from
// the nearer end so that an end far off screen (a segment reaching towards
// the eye) costs no precision near the other.
float distanceSquared(vec2 p, vec2 a, vec2 b) {
  precise vec2 d = b - a;
  precise float len = length(d);
  precise vec2 dir = len > 1e-4 ? d / len : vec2(1.0, 0.0);
  precise vec2 fromStart = p - a, fromEnd = p - b;
  precise float alongStart = dot(fromStart, dir), alongEnd = dot(fromEnd, dir);
  if (alongStart <= 0.0) return dot(fromStart, fromStart);
  if (alongEnd >= 0.0) return dot(fromEnd, fromEnd);
  precise vec2 normal = vec2(-dir.y, dir.x);
  precise float across = -alongEnd < alongStart ? dot(fromEnd, normal) : dot(fromStart, normal);
  return across * across;
}

void main() {
  vec2 p = gl_FragCoord.xy;
  float own = distanceSquared(p, segmentStart, segmentEnd);
  if (hasPrevious == 1 && distanceSquared(p, previousStart, segmentStart) <= own) discard;
  if (hasNext == 1 && distanceSquared(p, segmentEnd, nextEnd) < own) discard;
  float coverage = clamp(0.5 * widthPx + 0.5 - sqrt(own), 0.0, min(widthPx, 1.0));
  if (coverage <= 0.0) discard;
  fragColor = vec4(encodeSrgb(lineColor.rgb), lineColor.a * coverage);
}
