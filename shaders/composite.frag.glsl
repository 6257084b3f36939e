#version 450 core
// The last pass of a frame, one fragment per output pixel: the average of
// the pixel's scene samples (the MSAA resolve), the view's backdrop gradient
// put behind them (the scene is premultiplied colour over transparent black:
// out = c + (1 − a)·backdrop, the "over" operator, exact for any stack of
// blended layers), and a vertical flip: output row r (counted from the
// bottom, as GL does) reads scene row sourceTopRow − r, so the read-back
// delivers the image top row first. Values are sRGB-encoded bytes
// throughout, as the scene's blending is.
#ifndef SAMPLES
#define SAMPLES 4
#endif
#if SAMPLES > 1
uniform sampler2DMS scene;
#else
uniform sampler2D scene;
#endif
uniform int sourceTopRow;    // image height − 1
uniform float opaqueOutput;  // 1: alpha 1 everywhere, 0: keep coverage (transparent PNG)
in vec3 vBackdrop;           // 0 where there is none
out vec4 fragColor;

void main() {
  ivec2 src = ivec2(int(gl_FragCoord.x), sourceTopRow - int(gl_FragCoord.y));
#if SAMPLES > 1
  vec4 c = vec4(0.0);
  for (int i = 0; i < SAMPLES; ++i) c += texelFetch(scene, src, i);
  c *= 1.0 / float(SAMPLES);
#else
  vec4 c = texelFetch(scene, src, 0);
#endif
  fragColor = vec4(c.rgb + (1.0 - c.a) * vBackdrop, max(c.a, opaqueOutput));
}
