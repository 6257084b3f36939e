#version 450 core
// One triangle that covers the viewport: a vertical gradient from the
// bottom to the top colour. The two ends are sRGB-encoded here, per vertex,
// and the ramp is interpolated in display space: a smooth backdrop that costs
// the fragment stage nothing.
uniform vec3 topColor;     // linear RGB
uniform vec3 bottomColor;  // linear RGB
out vec3 vColor;
vec3 encodeSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  // p.y = 0 at the bottom edge, 1 at the top, 2 beyond it (off screen).
  vec3 bottom = encodeSrgb(bottomColor), top = encodeSrgb(topColor);
  vColor = bottom + (top - bottom) * p.y;
  gl_Position = vec4(p * 2.0 - 1.0, 1.0, 1.0);  // the far plane: drawn only where nothing else is
}
