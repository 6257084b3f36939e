#version 450 core
// The multisampled opaque meshes resolved into the one-sample scene: each
// pixel the rounded mean of its samples. The samples are read as packed
// words (an R32UI view of the RGBA8 samples: R in the low byte, little
// endian) and summed two channels at a time in 16-bit lanes, written as a
// packed word into an R32UI view of the scene: llvmpipe fetches one word per
// sample instead of unpacking four channels to floats and packing them
// again (a glBlitFramebuffer resolve cost a 1080p still about 6 ms more).
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
uniform usampler2DMS samples;
out uint fragColor;  // packed RGBA8, R in the low byte

const uint kLow = 0x00FF00FFu;  // bytes 0 and 2 of a word, in 16-bit lanes

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  uint rb = 0u, ga = 0u;  // R and B (G and A) sums, each ≤ 4·255 in its lane
  for (int i = 0; i < SAMPLES; ++i) {
    uint t = texelFetch(samples, p, i).r;
    rb += t & kLow;
    ga += (t >> 8u) & kLow;
  }
  // Rounded means; the mask drops what the shift moved across lanes.
  uint half_ = (1u << SAMPLE_SHIFT) >> 1u;
  rb = ((rb + half_ * 0x00010001u) >> SAMPLE_SHIFT) & kLow;
  ga = ((ga + half_ * 0x00010001u) >> SAMPLE_SHIFT) & kLow;
  fragColor = rb | (ga << 8u);
}
