#version 450 core
// One triangle that covers the viewport (a view's rectangle of the output),
// carrying the backdrop gradient: it is linear in y, so interpolating its
// three vertex values is exact and costs the fragment stage no arithmetic.
uniform float backdropWeight;  // 1: the view has a backdrop, 0: none
uniform vec3 topColor;         // sRGB-encoded backdrop at the view's top edge
uniform vec3 bottomColor;      // ... and at its bottom edge
out vec3 vBackdrop;
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  // Output rows are image rows, top-down: p.y = 0 is the view's top edge,
  // 1 its bottom edge, 2 beyond it.
  vBackdrop = backdropWeight * (topColor + (bottomColor - topColor) * p.y);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
