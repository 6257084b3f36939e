#version 450 core
// Lit meshes: world-space position and normal for lighting, light-space
// position for the shadow map lookup.
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

out vec3 vWorldPosition;
out vec3 vNormal;
out vec2 vUv;
out vec4 vLightClip;

void main() {
  vec4 world = worldFromModel * vec4(aPosition, 1.0);
  vWorldPosition = world.xyz;
  vNormal = normalWorldFromModel * aNormal;
  vUv = aUv;
  vLightClip = lightClipFromWorld * world;
  vec2 box = vLightClip.xy / vLightClip.w;
  gl_ClipDistance[0] = clipToShadowBox ? 1.0 - box.x : 1.0;
  gl_ClipDistance[1] = clipToShadowBox ? 1.0 + box.x : 1.0;
  gl_ClipDistance[2] = clipToShadowBox ? 1.0 - box.y : 1.0;
  gl_ClipDistance[3] = clipToShadowBox ? 1.0 + box.y : 1.0;
  gl_ClipDistance[4] = dot(cutPlane, world);
  gl_Position = clipFromWorld * world;
}
