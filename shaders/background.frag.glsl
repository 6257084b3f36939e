#version 450 core
// A soft vertical gradient, interpolated in linear light.
in float vY;
uniform vec3 topColor;
uniform vec3 bottomColor;
out vec4 fragColor;
vec3 encodeSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}
void main() { fragColor = vec4(encodeSrgb(mix(bottomColor, topColor, smoothstep(0.0, 1.0, vY))), 1.0); }
