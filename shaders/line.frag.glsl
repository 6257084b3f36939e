#version 450 core
uniform vec4 lineColor;  // linear RGB + alpha
out vec4 fragColor;
#include "srgb"
void main() { fragColor = vec4(encodeSrgb(lineColor.rgb), lineColor.a); }
