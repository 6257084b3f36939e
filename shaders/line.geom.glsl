#version 450 core
// Core-profile GL has no wide lines: each segment becomes a screen-space quad
// of constant pixel width, extended by half a width at both ends so that the
// segments of a polyline overlap at the joints instead of leaving notches.
// A small depth bias keeps a path drawn on a surface in front of it.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 viewportSize;
uniform float widthPx;
uniform float depthBias;

void emit(vec2 screen, vec4 clip) {
  gl_Position = vec4(screen / (0.5 * viewportSize) * clip.w, clip.z - depthBias * clip.w, clip.w);
  EmitVertex();
}

void main() {
  vec4 p0 = gl_in[0].gl_Position, p1 = gl_in[1].gl_Position;
  if (p0.w <= 1e-6 || p1.w <= 1e-6) return;  // behind the camera: skip the segment
  vec2 s0 = p0.xy / p0.w * 0.5 * viewportSize;
  vec2 s1 = p1.xy / p1.w * 0.5 * viewportSize;
  vec2 d = s1 - s0;
  float len = length(d);
  vec2 dir = len > 1e-4 ? d / len : vec2(1.0, 0.0);
  vec2 side = vec2(-dir.y, dir.x) * 0.5 * widthPx;
  vec2 ext = dir * 0.5 * widthPx;
  emit(s0 - ext - side, p0);
  emit(s0 - ext + side, p0);
  emit(s1 + ext - side, p1);
  emit(s1 + ext + side, p1);
  EndPrimitive();
}
