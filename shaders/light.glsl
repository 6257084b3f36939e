// The key light's fill and highlight, one formula for mesh.vert (lit per
// vertex) and mesh.frag (per pixel). Included by an include line naming
// light.

// The ambient fill's colour for unit normal n: sky light from +z, a warm
// bounce from below.
vec3 hemisphere(vec3 n) { return mix(vec3(0.62, 0.58, 0.55), vec3(1.0, 1.0, 1.02), 0.5 + 0.5 * n.z); }

// Blinn–Phong: the highlight's strength for unit normal n, unit vectors v
// (towards the eye) and l (towards the light), ndl = max(n·l, 0); none
// where the light is behind the surface.
float highlight(vec3 n, vec3 v, vec3 l, float ndl, float strength, float exponent) {
  vec3 h = normalize(l + v);
  return ndl > 0.0 ? strength * pow(max(dot(n, h), 0.0), exponent) : 0.0;
}
