#version 450 core
// The last pass of a frame, one fragment per output pixel: the average of
// the pixel's scene samples (the MSAA resolve), the view's backdrop gradient
// put behind them (the scene is premultiplied colour over transparent black:
// out = c + (1 − a)·backdrop, the "over" operator, exact for any stack of
// blended layers), and a vertical flip: output row r (counted from the
// bottom, as GL does) reads scene row sourceTopRow − r, so the read-back
// delivers the image top row first. Values are sRGB-encoded bytes
// throughout, as the scene's blending is.
//
// The samples are read as packed words (an R32UI view of the RGBA8 scene:
// R in the low byte, little endian) and averaged two channels at a time in
// 16-bit lanes: llvmpipe then fetches one word per sample instead of
// unpacking four channels to floats and packing them again (measured: a
// 1080p frame 6 ms of CPU cheaper at 1 sample; at 4 the fetches dominate).
#ifndef SAMPLES
#define SAMPLES 4
#endif
#if SAMPLES == 4
#define SAMPLE_SHIFT 2u
#elif SAMPLES == 2
#define SAMPLE_SHIFT 1u
#else
#define SAMPLE_SHIFT 0u
#endif
#if SAMPLES > 1
uniform usampler2DMS scene;
#else
uniform usampler2D scene;
#endif
uniform int sourceTopRow;   // image height − 1
uniform uint opaqueAlpha;   // 255: alpha 255 everywhere, 0: keep coverage (transparent PNG)
in vec3 vBackdrop;          // sRGB-encoded in [0, 1]; 0 where there is none
out uint fragColor;         // packed RGBA8, R in the low byte

const uint kLow = 0x00FF00FFu;  // bytes 0 and 2 of a word, in 16-bit lanes

void main() {
  ivec2 src = ivec2(int(gl_FragCoord.x), sourceTopRow - int(gl_FragCoord.y));
  uint rb = 0u, ga = 0u;  // R and B (G and A) sums, each ≤ 4·255 in its lane
  for (int i = 0; i < SAMPLES; ++i) {
    uint t = texelFetch(scene, src, i).r;
    rb += t & kLow;
    ga += (t >> 8u) & kLow;
  }
  // Rounded means; the mask drops what the shift moved across lanes.
  uint half_ = (1u << SAMPLE_SHIFT) >> 1u;
  rb = ((rb + half_ * 0x00010001u) >> SAMPLE_SHIFT) & kLow;
  ga = ((ga + half_ * 0x00010001u) >> SAMPLE_SHIFT) & kLow;
  uint a = ga >> 16u;
  // The backdrop behind what the samples left uncovered.
  uvec3 behind = uvec3(vBackdrop * float(255u - a) + 0.5);
  uint r = min((rb & 0xFFu) + behind.r, 255u);
  uint g = min((ga & 0xFFu) + behind.g, 255u);
  uint b = min((rb >> 16u) + behind.b, 255u);
  fragColor = r | (g << 8u) | (b << 16u) | (max(a, opaqueAlpha) << 24u);
}
