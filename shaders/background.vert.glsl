#version 450 core
// One triangle that covers the viewport; vY runs 0 (bottom) → 1 (top).
out float vY;
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  vY = p.y;
  gl_Position = vec4(p * 2.0 - 1.0, 0.9999, 1.0);
}
