#version 450 core
// Depth alone, of a sphere seen from the key light, ray-cast per texel:
// the light is orthographic, so the sphere's outline in the shadow map is a
// circle, and the point nearest the light over a texel's centre p lies at
// z = c_z − k √(1 − |p − c|² / ρ²) in the map's normalized device
// coordinates (c the centre, ρ its radius across the light, k along it).
// The renderer draws the circle's square with impostor.vert. Its
// triangles would cost llvmpipe a setup and binning each (thousands for a
// ball); their outline differs from the circle by a tenth of a texel.
uniform vec2 mapSize;      // texels
uniform vec4 sphereNdc;    // c (x, y, z) and ρ
uniform float depthRadius;  // k
void main() {
  vec2 across = (2.0 * gl_FragCoord.xy / mapSize - 1.0 - sphereNdc.xy) / sphereNdc.w;
  float outside = dot(across, across);
  if (outside > 1.0) discard;
  float z = sphereNdc.z - depthRadius * sqrt(1.0 - outside);
  // Beyond the near or far plane the triangles were clipped away.
  if (abs(z) > 1.0) discard;
  gl_FragDepth = 0.5 + 0.5 * z;
}
