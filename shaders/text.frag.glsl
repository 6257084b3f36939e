#version 450 core
in vec2 vUv;
uniform sampler2D glyphAtlas;
uniform vec4 textColor;  // linear RGB + alpha
uniform bool solid;      // rectangles: ignore the atlas
out vec4 fragColor;
#include "srgb"
void main() {
  float coverage = solid ? 1.0 : texture(glyphAtlas, vUv).r;
  fragColor = vec4(encodeSrgb(textColor.rgb), textColor.a * coverage);
}
