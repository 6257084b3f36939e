#version 450 core
// Keeps the samples of line.geom's quad that lie inside the segment's capsule
// (within half a width of it, in window pixels). Coverage is computed per
// sample from the target's own sample positions, so a line's edges and round
// ends are antialiased like any triangle edge, and a pixel's result depends
// only on its position: a line drawn under a scissor gives the same bytes as
// drawn whole. The shader still runs once per pixel (gl_SampleID is not read).
// COVERAGE 1 (a framebuffer of one sample, where one sample would alias):
// the pixel's coverage instead, from its centre's distance to the capsule
// through a one-pixel ramp (a box filter across a straight edge), as alpha.
#ifndef COVERAGE
#define COVERAGE 0
#endif
uniform vec4 lineColor;  // linear RGB + alpha
uniform float widthPx;
uniform int sampleCount;           // of the bound framebuffer: 1 to 16
uniform vec2 samplePositions[16];  // within a pixel, from its lower-left corner
flat in vec2 segmentStart;
flat in vec2 segmentEnd;
out vec4 fragColor;
#include "srgb"

// Squared distance from p to the segment. Lengths are measured from the
// nearer end so that an end far off screen (a segment reaching towards the
// eye) costs no precision near the other.
float distanceSquared(vec2 p) {
  vec2 d = segmentEnd - segmentStart;
  float len = length(d);
  vec2 dir = len > 1e-4 ? d / len : vec2(1.0, 0.0);
  vec2 fromStart = p - segmentStart, fromEnd = p - segmentEnd;
  float alongStart = dot(fromStart, dir), alongEnd = dot(fromEnd, dir);
  if (alongStart <= 0.0) return dot(fromStart, fromStart);
  if (alongEnd >= 0.0) return dot(fromEnd, fromEnd);
  vec2 normal = vec2(-dir.y, dir.x);
  float across = -alongEnd < alongStart ? dot(fromEnd, normal) : dot(fromStart, normal);
  return across * across;
}

void main() {
#if COVERAGE
  float radius = 0.5 * widthPx;
  float coverage = clamp(radius + 0.5 - sqrt(distanceSquared(gl_FragCoord.xy)), 0.0, min(widthPx, 1.0));
  if (coverage <= 0.0) discard;
  fragColor = vec4(encodeSrgb(lineColor.rgb), lineColor.a * coverage);
#else
  vec2 pixel = floor(gl_FragCoord.xy);
  float radiusSquared = 0.25 * widthPx * widthPx;
  int mask = 0;
  for (int i = 0; i < sampleCount; ++i)
    if (distanceSquared(pixel + samplePositions[i]) <= radiusSquared) mask |= 1 << i;
  if (mask == 0) discard;
  gl_SampleMask[0] = mask;
  fragColor = vec4(encodeSrgb(lineColor.rgb), lineColor.a);
#endif
}
