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
  gl_Position = clipFromWorld * world;
}
