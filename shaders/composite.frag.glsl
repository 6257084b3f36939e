#version 450 core
// The last pass of a frame, one fragment per output pixel: the scene's
// pixel (one sample: the multisampled steps are resolved into it before),
// the view's backdrop gradient put behind it (the scene is premultiplied
// colour over transparent black: out = c + (1 − a)·backdrop, the "over"
// operator, exact for any stack of blended layers), and a vertical flip: output row r (counted from the
// bottom, as GL does) reads scene row sourceTopRow − r, so the read-back
// delivers the image top row first. Values are sRGB-encoded bytes
// throughout, as the scene's blending is.
//
// The pixel is read as a packed word (an R32UI view of the RGBA8 scene: R in
// the low byte, little endian): llvmpipe then fetches one word instead of
// unpacking four channels to floats and packing them again (measured: a
// 1080p frame 6 ms of CPU cheaper).
uniform usampler2D scene;
uniform int sourceTopRow;   // image height − 1
uniform uint opaqueAlpha;   // 255: alpha 255 everywhere, 0: keep coverage (transparent PNG)
in vec3 vBackdrop;          // sRGB-encoded in [0, 1]; 0 where there is none
out uint fragColor;         // packed RGBA8, R in the low byte

void main() {
  uint t = texelFetch(scene, ivec2(int(gl_FragCoord.x), sourceTopRow - int(gl_FragCoord.y)), 0).r;
  uint a = t >> 24u;
  // The backdrop behind what the scene left uncovered.
  uvec3 behind = uvec3(vBackdrop * float(255u - a) + 0.5);
  uint r = min((t & 0xFFu) + behind.r, 255u);
  uint g = min(((t >> 8u) & 0xFFu) + behind.g, 255u);
  uint b = min(((t >> 16u) & 0xFFu) + behind.b, 255u);
  fragColor = r | (g << 8u) | (b << 16u) | (max(a, opaqueAlpha) << 24u);
}
