#version 450 core
// One triangle that covers the viewport: the resolve pass's one fragment
// per pixel. Vertices (0,0), (2,0), (0,2) in viewport units, so the
// triangle's clipped part is the viewport's square.
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
