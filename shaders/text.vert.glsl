#version 450 core
// Glyph quads and solid rectangles in pixel coordinates (top-left origin).
layout(location = 0) in vec2 aPixel;
layout(location = 1) in vec2 aUv;
uniform vec2 viewportSize;
out vec2 vUv;
void main() {
  vUv = aUv;
  gl_Position = vec4(aPixel.x / viewportSize.x * 2.0 - 1.0, 1.0 - aPixel.y / viewportSize.y * 2.0, 0.0, 1.0);
}
