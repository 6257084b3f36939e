#version 450 core
// Core-profile GL has no wide lines: each segment becomes a capsule of
// constant pixel width (all points within half a width of the segment, in
// window pixels). This stage emits the capsule's bounding quad, a screen-space
// rectangle grown by half a width plus a pixel on every side, and hands the
// segment's window-space ends, and its neighbours' far ends (the strip is
// drawn with adjacency), to line.frag, which gives each pixel to one
// segment of the polyline and its coverage to that one: where segments meet,
// their end discs overlap (round joins and round caps) without blending
// twice. A small depth bias keeps a path drawn on a surface in front of it.
layout(lines_adjacency) in;
layout(triangle_strip, max_vertices = 4) out;

uniform vec2 viewportOrigin;  // window pixels of the viewport's lower-left corner
uniform vec2 viewportSize;
uniform float widthPx;
uniform float depthBias;

flat out vec2 segmentStart;  // window pixels
flat out vec2 segmentEnd;
flat out vec2 previousStart;  // the segment before ends at segmentStart; hasPrevious = 0: none
flat out vec2 nextEnd;        // the segment after starts at segmentEnd; hasNext = 0: none
flat out int hasPrevious;
flat out int hasNext;

vec2 windowStart, windowEnd, windowPrevious, windowNext;
int previousShown, nextShown;

void emit(vec2 screen, vec4 clip) {
  gl_Position = vec4(screen / (0.5 * viewportSize) * clip.w, clip.z - depthBias * clip.w, clip.w);
  segmentStart = windowStart;  // outputs are undefined after each EmitVertex
  segmentEnd = windowEnd;
  previousStart = windowPrevious;
  nextEnd = windowNext;
  hasPrevious = previousShown;
  hasNext = nextShown;
  EmitVertex();
}

// `precise`: a vertex's window position must come out the same in each of
// the (up to four) segments that read it (see line.frag).
vec2 window(vec4 clip, vec2 centre) {
  precise vec2 w = centre + clip.xy / clip.w * 0.5 * viewportSize;
  return w;
}

void main() {
  vec4 before = gl_in[0].gl_Position, p0 = gl_in[1].gl_Position, p1 = gl_in[2].gl_Position,
       after = gl_in[3].gl_Position;
  if (p0.w <= 1e-6 || p1.w <= 1e-6) return;  // behind the camera: skip the segment
  // The polyline's ends are repeated (see the renderer): no neighbour there.
  previousShown = before != p0 && before.w > 1e-6 ? 1 : 0;
  nextShown = after != p1 && after.w > 1e-6 ? 1 : 0;
  vec2 centre = viewportOrigin + 0.5 * viewportSize;
  windowStart = window(p0, centre);
  windowEnd = window(p1, centre);
  windowPrevious = previousShown == 1 ? window(before, centre) : windowStart;
  windowNext = nextShown == 1 ? window(after, centre) : windowEnd;
  // Pixels from the viewport's centre.
  vec2 s0 = windowStart - centre, s1 = windowEnd - centre;
  vec2 d = s1 - s0;
  float len = length(d);
  vec2 dir = len > 1e-4 ? d / len : vec2(1.0, 0.0);
  float reach = 0.5 * widthPx + 1.0;  // the capsule's radius and a pixel for the coverage ramp
  vec2 side = vec2(-dir.y, dir.x) * reach;
  vec2 ext = dir * reach;
  emit(s0 - ext - side, p0);
  emit(s0 - ext + side, p0);
  emit(s1 + ext - side, p1);
  emit(s1 + ext + side, p1);
  EndPrimitive();
}
