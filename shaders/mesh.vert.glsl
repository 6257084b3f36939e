#version 450 core
// Lit meshes: world-space position and normal for lighting, light-space
// position for the shadow map lookup. The renderer prepends the variant's
// defines (see mesh.frag); matte lit variants are lit here, per vertex.
#ifndef LIT
#define LIT 1
#endif
#ifndef SPECULAR
#define SPECULAR 1
#endif
#ifndef VERTEX_LIT
#define VERTEX_LIT 0
#endif
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 worldFromModel;
uniform mat3 normalWorldFromModel;
uniform mat4 clipFromWorld;
uniform mat4 lightClipFromWorld;
// Shadow receivers are drawn in two passes (see renderer.cpp): inside the
// shadow box, clipped to it, with the shadow filter; then the rest without.
uniform bool clipToShadowBox;
uniform vec4 cutPlane;  // the material's cut-away (0, 0, 0, 1: none)

out float gl_ClipDistance[5];

centroid out vec3 vWorldPosition;
centroid out vec3 vNormal;
centroid out vec2 vUv;
centroid out vec4 vLightClip;

#if LIT && (!SPECULAR || VERTEX_LIT)
uniform vec3 towardLight;  // unit
uniform vec3 lightColor;
uniform float ambient;
uniform vec3 cameraPosition;
uniform vec3 color;
#include "srgb"
#include "light"
#endif
#if LIT && !SPECULAR
// Matte surfaces are lit per vertex (Gouraud): without a highlight the
// light varies slowly across a triangle (on a plane not at all), and the
// fragment stage, which llvmpipe pays for per pixel, is spared two
// normalisations and the hemisphere blend (about 7 ms of a 1080p frame).
// Their colours leave here sRGB-encoded, both of a checker's: outside the
// shadow box a pixel only mixes them (the encoding was another 2–3 ms of a
// 1080p floor). The light is so interpolated in sRGB, not linearly: within
// a level where it varies slowly, and the same on a plane. A checker's edge
// pixels blend its colours in sRGB too, as a resolve of samples does and
// as the quality table's reference, a box filter of sRGB bytes, does.
uniform bool twoSided;        // light the side that faces the camera
uniform bool backFacesShown;  // Cull::Front: the back side is the visible one
uniform vec3 color2;
centroid out vec3 vAmbient;  // ambient · hemisphere
centroid out float vNdl;     // max(n·l, 0)
centroid out float vGrazing;  // translucent materials thicken at grazing angles: alpha factor
centroid out vec3 vLitSrgb;   // color lit, unshadowed, sRGB-encoded
centroid out vec3 vLitSrgb2;  // color2 so
#elif LIT && VERTEX_LIT
// An arrow's shaft and head (the renderer's own cylinder and cone, opaque,
// back faces culled) are lit per vertex with the highlight too, and leave
// here sRGB-encoded: their facets are a pixel or two wide at any size they
// are drawn, so the light interpolated across one is the light per pixel
// to within rounding, and the fragment stage, which llvmpipe pays for on
// every pixel of every sample tile they reach, only passes it on (about
// 0.7 ms of a fixed-camera 1080p frame).
uniform float specular;
uniform float shininess;
centroid out vec3 vLitSrgb;
#endif

void main() {
  vec4 world = worldFromModel * vec4(aPosition, 1.0);
  vWorldPosition = world.xyz;
  vNormal = normalWorldFromModel * aNormal;
  vUv = aUv;
  vLightClip = lightClipFromWorld * world;
#if LIT && !SPECULAR
  vec3 n = normalize(vNormal);
  vec3 v = normalize(cameraPosition - world.xyz);
  n = twoSided ? faceforward(n, -v, n) : (backFacesShown ? -n : n);
  vAmbient = ambient * hemisphere(n);
  vNdl = max(dot(n, towardLight), 0.0);
  vGrazing = 1.0 + 2.0 * pow(1.0 - abs(dot(n, v)), 3.0);
  vec3 light = vAmbient + (1.0 - ambient) * lightColor * vNdl;
  vLitSrgb = encodeSrgb(color * light);
  vLitSrgb2 = encodeSrgb(color2 * light);
#elif LIT && VERTEX_LIT
  vec3 n = normalize(vNormal);
  vec3 v = normalize(cameraPosition - world.xyz);
  float ndl = max(dot(n, towardLight), 0.0);
  float spec = highlight(n, v, towardLight, ndl, specular, shininess);
  vLitSrgb = encodeSrgb(color * (ambient * hemisphere(n) + (1.0 - ambient) * lightColor * ndl) + spec * lightColor);
#endif
  vec2 box = vLightClip.xy / vLightClip.w;
  gl_ClipDistance[0] = clipToShadowBox ? 1.0 - box.x : 1.0;
  gl_ClipDistance[1] = clipToShadowBox ? 1.0 + box.x : 1.0;
  gl_ClipDistance[2] = clipToShadowBox ? 1.0 - box.y : 1.0;
  gl_ClipDistance[3] = clipToShadowBox ? 1.0 + box.y : 1.0;
  gl_ClipDistance[4] = dot(cutPlane, world);
  gl_Position = clipFromWorld * world;
}
