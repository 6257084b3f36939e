#version 450 core
// A screen rectangle that holds (part of) a ray-cast sphere (mesh.frag with
// IMPOSTOR 1), as one triangle of three vertices without attributes, twice
// the rectangle's width and height: the renderer scissors it to the
// rectangle. Depth comes from the fragment stage (gl_FragDepth), or is
// ndcDepth.
uniform vec4 ndcRect;   // x0, y0, x1, y1 in the viewport's normalized device coordinates
uniform float ndcDepth;  // where the fragment stage gives no depth of its own (IMPOSTOR 2)

out float gl_ClipDistance[5];

void main() {
  vec2 corner = vec2(gl_VertexID == 1 ? 2.0 : 0.0, gl_VertexID == 2 ? 2.0 : 0.0);
  gl_Position = vec4(mix(ndcRect.xy, ndcRect.zw, corner), ndcDepth, 1.0);
  for (int i = 0; i < 5; ++i) gl_ClipDistance[i] = 1.0;  // the renderer enables them for meshes
}
