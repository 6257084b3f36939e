#version 450 core
// Blinn–Phong in linear light with a hemispheric ambient fill and a
// percentage-closer-filtered shadow (a soft key light), then sRGB encoding:
// the framebuffer holds display-ready sRGB bytes.
//
// Compiled in variants (the renderer prepends the defines): llvmpipe runs
// both sides of every branch, even on uniforms, so features a draw does not
// use must be compiled out, not skipped.
//   PATTERN  0 plain, 1 checker, 2 texture, 3 solid checker (world cubes)
//   SHADOWED 1: sample the shadow map
//   LIT      0: flat colour (no lighting)
//   SPECULAR 0: no highlight, and lit per vertex (see mesh.vert)
//   VERTEX_LIT 1: lit per vertex with the highlight (an arrow, see mesh.vert)
//   IMPOSTOR 1: a unit sphere ray-cast per pixel (impostor.vert draws its
//               screen rectangle) with analytic edge coverage as alpha, for
//               framebuffers of one sample (see castSphere); 2: the same,
//               premultiplied, without a depth of its own (the renderer's
//               pass under what a pixel shows: the rectangle lies at the
//               sphere's far depth, so llvmpipe tests it before shading)
//   CAPTURE  1: IMPOSTOR 1 drawn into a capture (the renderer's
//               SphereCapture), which keeps the depth it gives a pixel too
//   CONE_CUT 1: the material's porthole (cutCone) is discarded
#ifndef PATTERN
#define PATTERN 0
#endif
#ifndef SHADOWED
#define SHADOWED 0
#endif
#ifndef LIT
#define LIT 1
#endif
#ifndef SPECULAR
#define SPECULAR 1
#endif
#ifndef IMPOSTOR
#define IMPOSTOR 0
#endif
#ifndef VERTEX_LIT
#define VERTEX_LIT 0
#endif
#ifndef CAPTURE
#define CAPTURE 0
#endif
#ifndef CONE_CUT
#define CONE_CUT 0
#endif

#if IMPOSTOR
// What mesh.vert would interpolate, computed per pixel by castSphere.
vec3 vWorldPosition;
vec3 vNormal;
vec2 vUv;
vec4 vLightClip;
float latitudeRadius;  // of the point's direction in the model: distance from its z axis
uniform mat4 worldFromModel;    // a similarity: rotation, uniform scale, translation
uniform mat4 worldFromClip;     // inverse(clipFromWorld)
uniform mat4 clipFromWorld;
uniform mat4 lightClipFromWorld;
uniform vec4 viewportRect;      // window pixels: x, y, width, height
#else
centroid in vec3 vWorldPosition;
centroid in vec3 vNormal;
centroid in vec2 vUv;
centroid in vec4 vLightClip;
#endif

uniform vec3 color;
uniform vec3 color2;
uniform float opacity;
uniform float specular;
uniform float shininess;
uniform vec2 patternScale;
uniform sampler2D albedoTexture;
uniform sampler2DShadow shadowMap;
uniform float shadowFilterRadius;  // PCF radius in shadow-map uv
uniform vec3 towardLight;
uniform vec3 lightColor;
uniform float ambient;
uniform vec3 cameraPosition;
uniform bool twoSided;  // light the side that faces the camera
#if CONE_CUT
// A porthole towards a hidden point: the cone from the eye through the
// sphere (xyz, radius w), nearer the eye than its centre, is cut away.
uniform vec4 cutCone;
#endif
#if LIT && !SPECULAR && !IMPOSTOR
centroid in vec3 vAmbient;
centroid in float vNdl;
centroid in float vGrazing;
centroid in vec3 vLitSrgb;
centroid in vec3 vLitSrgb2;
#elif LIT && VERTEX_LIT
centroid in vec3 vLitSrgb;
#endif

layout(location = 0) out vec4 fragColor;
#if CAPTURE
layout(location = 1) out float capturedDepth;
#endif

#include "srgb"
#include "light"

// Box-filtered checker (no aliasing at grazing angles). A box filter still
// lets through some of a pattern finer than the pixels (its sidelobes beat
// with the pixel grid: moiré on a steep wall whose cells are stretched), so
// the contrast fades to the mean as a cell's footprint shrinks from two
// pixels to one, where no checker can be shown anyway.
float checker(vec2 p) {
  vec2 w = abs(dFdx(p)) + abs(dFdy(p)) + 0.001;
  vec2 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;
  float contrast = 1.0 - smoothstep(0.5, 1.0, max(w.x, w.y));
  return 0.5 - 0.5 * i.x * i.y * contrast;
}

// The same filter in three dimensions: cubes in world space.
float solidChecker(vec3 p) {
  vec3 w = abs(dFdx(p)) + abs(dFdy(p)) + 0.001;
  vec3 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;
  float contrast = 1.0 - smoothstep(0.5, 1.0, max(w.x, max(w.y, w.z)));
  return 0.5 - 0.5 * i.x * i.y * i.z * contrast;
}

#if SHADOWED
// Sixteen taps on a Poisson disc, each a bilinear 2×2 comparison, with the
// disc turned per pixel by interleaved gradient noise (a function of the
// pixel position: deterministic): a smooth penumbra without rings. Only the
// shadow box pays for this (see the renderer).
const vec2 kPoisson[16] = vec2[](
    vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725), vec2(-0.09418410, -0.92938870),
    vec2(0.34495938, 0.29387760), vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464),
    vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379), vec2(0.44323325, -0.97511554),
    vec2(0.53742981, -0.47373420), vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
    vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590), vec2(0.19984126, 0.78641367),
    vec2(0.14383161, -0.14100790));

float shadowFactor(float ndl) {
  vec3 p = vLightClip.xyz / vLightClip.w * 0.5 + 0.5;
  float bias = 0.0015 + 0.004 * (1.0 - ndl);
  float angle = 6.2831853 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
  mat2 turn = mat2(cos(angle), sin(angle), -sin(angle), cos(angle)) * shadowFilterRadius;
  float lit = 0.0;
  for (int k = 0; k < 16; ++k) lit += texture(shadowMap, vec3(p.xy + turn * kPoisson[k], p.z - bias));
  // Outside the map (the draw is clipped to it, this guards its rim) is lit.
  return p.z >= 1.0 ? 1.0 : lit / 16.0;
}
#endif

#if IMPOSTOR
// The pixel centre's ray against the sphere |p − c| = r. The ray's closest
// approach to the centre, d, is r on the silhouette; its change per pixel
// (the gradient of d) turns r − d into pixels, so the pixel's coverage is
// that signed distance through a one-pixel ramp: the exact silhouette,
// antialiased as a box filter of a straight edge would. Pixels just outside
// the silhouette are shaded at the nearest point of the sphere. Texture
// coordinates are the uvSphere's (u = longitude, v = colatitude, of the
// model-space direction), with their derivatives taken across the seam
// u = 0 ≡ 1 so the mip level does not jump there. Everything depends on
// the pixel's position only: a rectangle drawn alone gives the same bytes.
float castSphere() {
  vec2 ndc = 2.0 * (gl_FragCoord.xy - viewportRect.xy) / viewportRect.zw - 1.0;
  vec4 nearPoint = worldFromClip * vec4(ndc, -1.0, 1.0);
  vec4 farPoint = worldFromClip * vec4(ndc, 1.0, 1.0);
  vec3 origin = nearPoint.xyz / nearPoint.w;
  vec3 dir = normalize(farPoint.xyz / farPoint.w - origin);
  vec3 centre = worldFromModel[3].xyz;
  float radius = length(worldFromModel[0].xyz);
  vec3 oc = origin - centre;
  float along = -dot(oc, dir);  // the closest approach's ray parameter
  vec3 closest = oc + along * dir;
  float d = length(closest);
  float perPixel = max(length(vec2(dFdx(d), dFdy(d))), 1e-9);
  float coverage = clamp(0.5 + (radius - d) / perPixel, 0.0, 1.0);
  vec3 fromCentre = d < radius ? oc + (along - sqrt(radius * radius - d * d)) * dir
                               : closest * (radius / max(d, 1e-30));
  vec3 world = centre + fromCentre;
  vWorldPosition = world;
  vNormal = fromCentre / radius;
  vLightClip = lightClipFromWorld * vec4(world, 1.0);
  vec3 model = normalize(transpose(mat3(worldFromModel)) * vNormal);
  latitudeRadius = length(model.xy);
  float u = atan(model.y, model.x) / 6.2831853 + 0.5;
  vUv = vec2(u, acos(clamp(model.z, -1.0, 1.0)) / 3.14159265);
#if IMPOSTOR == 1
  vec4 clip = clipFromWorld * vec4(world, 1.0);
  float depth = clamp(0.5 + 0.5 * clip.z / clip.w, 0.0, 1.0);
  gl_FragDepth = depth;
#if CAPTURE
  capturedDepth = depth;
#endif
#endif
  return coverage;
}

// Texture derivatives that wrap across the seam u = 0 ≡ 1, with u's scaled
// by the circle of latitude's radius: near a pole a pixel spans much of u
// but little of the texture's content (the mesh, whose triangles meet at
// the pole, does not see that span either), and the mip level would jump.
vec2 seamless(vec2 derivative, float radiusOfLatitude) {
  derivative.x = (derivative.x - round(derivative.x)) * radiusOfLatitude;
  return derivative;
}
#endif

// Alpha is coverage over the transparent scene (see composite.frag): an
// opaque material writes 1 even where its texture has alpha, as it is drawn
// without blending.
void main() {
#if LIT && VERTEX_LIT
  fragColor = vec4(vLitSrgb, 1.0);  // opaque (see mesh.vert)
  return;
#endif
#if IMPOSTOR
  float coverage = castSphere();
#endif
  vec3 albedo = color;
  float alpha = opacity;
#if PATTERN == 1
  albedo = mix(color, color2, checker(vUv * patternScale));
#elif PATTERN == 3
  albedo = mix(color, color2, solidChecker(vWorldPosition * patternScale.x));
#elif PATTERN == 2 && IMPOSTOR
  vec4 t = textureGrad(albedoTexture, vUv, seamless(dFdx(vUv), latitudeRadius), seamless(dFdy(vUv), latitudeRadius));
  albedo = t.rgb * color;
  alpha *= t.a;
#elif PATTERN == 2
  vec4 t = texture(albedoTexture, vUv);
  albedo = t.rgb * color;
  alpha *= t.a;
#endif
#if LIT && !SPECULAR && !IMPOSTOR
  // Matte: lit per vertex (see mesh.vert); a checker's two colours are
  // mixed in sRGB, also where the shadow darkens them per pixel.
  if (opacity < 1.0) alpha = clamp(alpha * vGrazing, 0.0, 1.0);
#if SHADOWED
  vec3 light = vAmbient + (1.0 - ambient) * lightColor * vNdl * shadowFactor(vNdl);
#if PATTERN == 1
  vec3 srgb = mix(encodeSrgb(color * light), encodeSrgb(color2 * light), checker(vUv * patternScale));
#elif PATTERN == 3
  vec3 srgb = mix(encodeSrgb(color * light), encodeSrgb(color2 * light), solidChecker(vWorldPosition * patternScale.x));
#else
  vec3 srgb = encodeSrgb(albedo * light);
#endif
#elif PATTERN == 1
  vec3 srgb = mix(vLitSrgb, vLitSrgb2, checker(vUv * patternScale));
#elif PATTERN == 3
  vec3 srgb = mix(vLitSrgb, vLitSrgb2, solidChecker(vWorldPosition * patternScale.x));
#elif PATTERN == 2
  vec3 srgb = encodeSrgb(albedo * (vAmbient + (1.0 - ambient) * lightColor * vNdl));
#else
  vec3 srgb = vLitSrgb;
#endif
  fragColor = vec4(srgb, opacity < 1.0 ? alpha : 1.0);
#elif LIT
  vec3 v = normalize(cameraPosition - vWorldPosition);
  vec3 n = normalize(vNormal);
#if !IMPOSTOR  // a ray-cast sphere's normal faces the camera
  n = twoSided ? faceforward(n, -v, n) : (gl_FrontFacing ? n : -n);
#endif
  vec3 l = towardLight;  // unit (the renderer normalises it)
  float ndl = max(dot(n, l), 0.0);
#if SHADOWED
  float shadow = shadowFactor(ndl);
#else
  float shadow = 1.0;
#endif
#if SPECULAR || IMPOSTOR
  float spec = highlight(n, v, l, ndl, specular, shininess);
#else
  const float spec = 0.0;
#endif
  vec3 c = albedo * (ambient * hemisphere(n) + (1.0 - ambient) * lightColor * ndl * shadow) + spec * shadow * lightColor;
  // Translucent surfaces (glass, the Bloch sphere) thicken at grazing angles.
  if (opacity < 1.0) alpha = clamp(alpha * (1.0 + 2.0 * pow(1.0 - abs(dot(n, v)), 3.0)), 0.0, 1.0);
  fragColor = vec4(encodeSrgb(c), opacity < 1.0 ? alpha : 1.0);
#else
  fragColor = vec4(encodeSrgb(albedo), opacity < 1.0 ? alpha : 1.0);
#endif
#if IMPOSTOR
  // Discarded here, not where it is known, so every pixel of a 2×2 quad has
  // run the derivatives above.
  if (coverage <= 0.0) discard;
  fragColor.a *= coverage;  // blended over what is behind (an opaque sphere's alpha is its coverage)
#if IMPOSTOR == 2
  fragColor.rgb *= fragColor.a;  // blended under what is drawn (see the renderer)
#endif
#endif
#if CONE_CUT && !IMPOSTOR
  // The porthole, discarded last (as above) so that every pixel of a 2×2
  // quad has run the checker's derivatives.
  vec3 axis = cutCone.xyz - cameraPosition;
  float axisLength = length(axis);
  vec3 q = vWorldPosition - cameraPosition;
  float along = dot(q, axis) / axisLength;
  if (along < axisLength && length(q - along * axis / axisLength) < cutCone.w * along / axisLength) discard;
#endif
}
