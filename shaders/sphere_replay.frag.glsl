#version 450 core
// A translucent ray-cast sphere replayed from its capture (the renderer's
// SphereCapture): each pixel gets the colour and the depth that mesh.frag
// (IMPOSTOR 1) gave it, so blending and the depth test see the same values;
// a pixel that mesh.frag discarded holds a negative depth and is discarded.
uniform sampler2D capturedColor;  // RGBA32F
uniform sampler2D capturedDepth;  // R32F
uniform ivec2 captureOrigin;      // the window pixel of the capture's texel (0, 0)

out vec4 fragColor;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy) - captureOrigin;
  float depth = texelFetch(capturedDepth, texel, 0).r;
  if (depth < 0.0) discard;
  gl_FragDepth = depth;
  fragColor = texelFetch(capturedColor, texel, 0);
}
