#version 450 core
uniform vec4 lineColor;  // linear RGB + alpha
out vec4 fragColor;
vec3 encodeSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}
void main() { fragColor = vec4(encodeSrgb(lineColor.rgb), lineColor.a); }
