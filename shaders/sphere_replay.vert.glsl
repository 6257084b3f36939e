#version 450 core
// The parts of a captured sphere that a frame redraws (see
// sphere_replay.frag), as rectangles of window pixels, two triangles each,
// all in one draw: the replay costs so little a pixel that a draw per part
// (drawn so for the ray cast, see the renderer's drawImpostorParts) would
// cost more than the pixels.
layout(location = 0) in vec3 windowPosition;  // pixels from the bottom left; z unused
uniform vec4 viewportRect;                    // window pixels: x, y, width, height

out float gl_ClipDistance[5];

void main() {
  gl_Position = vec4(2.0 * (windowPosition.xy - viewportRect.xy) / viewportRect.zw - 1.0, 0.0, 1.0);
  for (int i = 0; i < 5; ++i) gl_ClipDistance[i] = 1.0;  // the renderer enables them for meshes
}
