#version 450 core
in vec2 vUv;
uniform sampler2D glyphAtlas;
uniform vec4 textColor;  // linear RGB + alpha
uniform bool solid;      // rectangles: ignore the atlas
out vec4 fragColor;
vec3 encodeSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}
void main() {
  float coverage = solid ? 1.0 : texture(glyphAtlas, vUv).r;
  fragColor = vec4(encodeSrgb(textColor.rgb), textColor.a * coverage);
}
