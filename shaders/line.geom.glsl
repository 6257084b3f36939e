#version 450 core
// Core-profile GL has no wide lines: each segment becomes a capsule of
// constant pixel width (all points within half a width of the segment, in
// window pixels). This stage emits the capsule's bounding quad, a screen-space
// rectangle grown by half a width plus a pixel on every side, and hands the
// segment's window-space ends to line.frag, which keeps exactly the samples
// inside the capsule. Where segments meet, their end discs overlap: a
// polyline gets round joins and round caps, and being opaque, no beads.
// A small depth bias keeps a path drawn on a surface in front of it.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 viewportOrigin;  // window pixels of the viewport's lower-left corner
uniform vec2 viewportSize;
uniform float widthPx;
uniform float depthBias;

flat out vec2 segmentStart;  // window pixels
flat out vec2 segmentEnd;

vec2 windowStart, windowEnd;

void emit(vec2 screen, vec4 clip) {
  gl_Position = vec4(screen / (0.5 * viewportSize) * clip.w, clip.z - depthBias * clip.w, clip.w);
  segmentStart = windowStart;  // outputs are undefined after each EmitVertex
  segmentEnd = windowEnd;
  EmitVertex();
}

void main() {
  vec4 p0 = gl_in[0].gl_Position, p1 = gl_in[1].gl_Position;
  if (p0.w <= 1e-6 || p1.w <= 1e-6) return;  // behind the camera: skip the segment
  // Pixels from the viewport's centre.
  vec2 s0 = p0.xy / p0.w * 0.5 * viewportSize;
  vec2 s1 = p1.xy / p1.w * 0.5 * viewportSize;
  vec2 centre = viewportOrigin + 0.5 * viewportSize;
  windowStart = centre + s0;
  windowEnd = centre + s1;
  vec2 d = s1 - s0;
  float len = length(d);
  vec2 dir = len > 1e-4 ? d / len : vec2(1.0, 0.0);
  float reach = 0.5 * widthPx + 1.0;  // the capsule's radius and a pixel for rounding
  vec2 side = vec2(-dir.y, dir.x) * reach;
  vec2 ext = dir * reach;
  emit(s0 - ext - side, p0);
  emit(s0 - ext + side, p0);
  emit(s1 + ext - side, p1);
  emit(s1 + ext + side, p1);
  EndPrimitive();
}
