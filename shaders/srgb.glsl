// Linear → sRGB to within 0.4 of a level: the linear toe, and above it a
// three-square-root fit of 1.055 c^(1/2.4) − 0.055 (cheaper than pow on
// llvmpipe, which pays for it on every pixel). Included by the fragment
// shaders that write the final colour (an include line naming srgb).
vec3 encodeSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  vec3 s1 = sqrt(c), s2 = sqrt(s1), s3 = sqrt(s2);
  return mix(12.92 * c, 0.585122381 * s1 + 0.783140355 * s2 - 0.368262736 * s3, step(0.0031308, c));
}
