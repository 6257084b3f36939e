// SceneSpec — what a scene file asks for, as plain structs. Every default
// lives here, in the member initialisers, and docs/scene-reference.md shows the same
// values. Each key that was given remembers where (file:line:col or the --set
// argument) through SceneSpec::where().
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "scene/frame_rate.hpp"
#include "scene/path_kinds.hpp"
#include "scene/surface_kinds.hpp"

namespace rollspin::scene {

using Vec3 = std::array<double, 3>;

struct BallSpec {
  double radius = 1.0;         // R
  std::string texture;         // equirectangular PNG/JPG (relative to the scene file); "" = built-in tennis ball
  std::optional<Vec3> marker;  // body point whose direction is the tracked Bloch vector; default: the top n(0)
};

// [surface]: its kind and the kind's own keys, read and printed from the
// kind's declarations (geometry/surface_kinds.hpp), never named here.
struct SurfaceSpec {
  SurfaceKind kind = SurfaceKind::Plane;
  ParamSet params = ParamSet(surfaceKeyDecls(SurfaceKind::Plane));  // every key of the kind: given or default
  [[nodiscard]] double number(const std::string& key) const { return params.number(key); }
};

struct PathSpec {
  PathKind kind = PathKind::Circle;
  double turns = 1.0;                   // circle, parallel
  bool counterClockwise = true;         // direction = "ccw" | "cw"
  double length = 10.0;                 // line
  std::optional<Vec3> directionVector;  // line; default: horizontal in the plane (docs/scenes.md#the-file-format)
  double radius = 3.0;                  // circle: contact circle radius r
  double colatitudeDeg = 60.0;          // parallel: θ in degrees
  double startAzimuthDeg = 0.0;         // parallel: the azimuth φ at s = 0 (docs/conventions.md)
  // Curved surfaces (issue 3). Angles in degrees; docs/scenes.md#curved-surfaces-and-curves.
  double tubeAngleDeg = 0.0;                // torus parallel / meridian start: ψ (0 = outer equator)
  double height = 0.0;                      // cylinder parallel / helix / meridian: start height along the axis
  double azimuthDeg = 0.0;                  // meridian, loxodrome: φ0
  double colatitudeStartDeg = 30.0;         // sphere meridian, loxodrome: θ0
  double colatitudeEndDeg = 150.0;          // sphere meridian, loxodrome: θ1
  double pitchAngleDeg = 30.0;              // helix: β from the parallels
  double headingDeg = 45.0;                 // loxodrome: α from the meridians
  std::optional<Vec3> startPoint;           // geodesic: projected onto the surface; default per surface
  std::string u = "0.5 + t", v = "t";       // uv: surface parameters as expressions of t (valid on every surface)
  double tStart = 0.0, tEnd = 1.0;          // uv: range of t
  std::vector<std::vector<double>> points;  // points: [u, v] parameters or [x, y, z] points
  bool closed = false;                      // points: periodic spline / closed polygon
  std::string interpolation = "spline";     // points: "spline" | "polyline"
  double cornerRadius = 0.0;                // points, polyline: arc radius rounding each corner
  double curvatureStart = -4.0;             // clothoid: κ_g at s = 0
  double curvatureRate = 1.0;               // clothoid: α in κ_g = κ₀ + α s
};

struct PlateSpec {
  double radius = 0.0;  // R1: radius of the circle each plate point describes
};

// Limits (docs/getting-started.md#limits-and-errors), each named once: the
// key tables (scene_tables.cpp) and the jobs that check a flag use these.
inline constexpr long long kMaxSolverSteps = 100'000'000'000LL;  // ~10 min of magnus4
inline constexpr long long kMaxTimelineSamples = 100'000'000LL;
inline constexpr long long kMinImageSide = 1, kMaxImageSide = 8192;  // "8K": the renderer's size limit
inline constexpr long long kMaxStrobe = 200;
inline constexpr double kMinFps = 1.0, kMaxFps = 240.0;
inline constexpr double kMaxDurationSeconds = 36000.0, kMaxHoldSeconds = 3600.0, kMaxFadeSeconds = 10.0;
inline constexpr double kMinFovDeg = 5.0, kMaxFovDeg = 120.0;
inline constexpr double kMinFontScale = 0.25, kMaxFontScale = 4.0;
inline constexpr double kMinFigureWidthMm = 10.0, kMaxFigureWidthMm = 2000.0;
inline constexpr double kMinFontSizePt = 2.0, kMaxFontSizePt = 72.0;
inline constexpr double kMinDpi = 30.0, kMaxDpi = 2400.0;
inline constexpr double kMaxCrf = 51.0;
inline constexpr double kMaxCurvature = 1e6;  // a clothoid's |κ₀| and |α|
inline constexpr long long kMaxJpegQuality = 100;
inline constexpr std::array<long long, 3> kMsaaSamples{1, 2, 4};

struct SolverSpec {
  std::string method = "magnus4";   // exact | magnus2 | magnus4 | rk4 | frame4 | cf4 | magnus6 | rk45 | frame6a
  std::optional<long long> steps;   // default: automatic (docs/solver.md#how-many-steps-and-how-accurate)
  std::optional<double> tolerance;  // adaptive methods; default kDefaultTolerance; alone → frame6a
  bool errorEstimate = true;        // the a posteriori estimate of U(L) (a second solve); false skips it
  static constexpr double kDefaultTolerance = 1e-10;
};

struct TimelineSpec {
  std::optional<long long> samples;  // default: 60 per turn (+1)
};

enum class RenderLayout { SideBySide, Inset, Ball, Twin };

// [render]: stills and frames. Camera: orbit about `target` (default: the
// path's centre) at `distance` (default: frames the whole path), or `follow`.
struct RenderSpec {
  long long width = 1280;
  long long height = 720;
  RenderLayout layout = RenderLayout::SideBySide;
  long long strobe = 0;  // > 1: the ball at N evenly spaced positions in one image
  std::string title;     // "" = no title
  bool labels = true;    // axis, pole and live labels (s, angles)
  bool trails = true;    // the marker's and the field's trails
  bool shadow = true;    // the key light's shadow map
  bool transparent = false;
  bool burnCaptions = true;  // false: title and captions only in the subtitle track and sidecars, not the pixels
  long long msaa = 4;        // 1 | 2 | 4
  double azimuthDeg = -60.0;
  double elevationDeg = 28.0;
  std::optional<double> distance;
  std::optional<Vec3> target;
  bool follow = false;
  double fovDeg = 32.0;
  // A row name of media's output-format table (media/output_formats.def);
  // default: from the output's extension, else mp4 (a clip) or png (a still).
  std::optional<std::string> format;
  long long jpegQuality = 92;  // JPEG stills, 1 … 100
  double dpi = 300.0;          // vector figures: resolution of their raster parts (the shaded ball and surfaces)
  double fontScale =
      1.0;  // text size × this (docs/rendering.md#stills-and-images); body line ≥ 1/28 of the height at 1
  bool twinCameraFixed = true;  // twin_camera: "fixed" (the first shot's view throughout) or "linked"
  // GL context (render/gl_backends.cpp): "auto" or a backend of the table, and
  // for EGL a device index or DRM path; unset: ROLLSPIN_GL / ROLLSPIN_EGL_DEVICE.
  std::optional<std::string> backend;
  std::optional<std::string> device;
};

// [figure]: a still as a publication figure (PDF/SVG, docs/figures.md): its
// physical width, the labels' font and size, the page.
struct FigureSpec {
  double widthMm = 120.0;            // figure.width_mm, or figure.width_in × 25.4
  std::string font = "DejaVu Sans";  // a fontconfig family name
  std::optional<double> fontSizePt;  // body text size; default: the still's proportions
  bool transparent = true;           // false: the views' backdrop gradients, as in the PNG
};

// [labels]: facts of the scene, computed from the solver (motion/scene_facts)
// and printed next to the paper's closed form. Each applies to some kinds
// only (factRule).
enum class Fact {
  Delta,       // rotation in the rolling frame after the circuit vs δ (circle, parallel)
  Marks,       // marks every path angle β that turns the ball by π (circle on a plane)
  Turns,       // turns in the lab and relative to the radius line (parallel at the equator)
  PhaseSplit,  // spinor phase = dynamic + geometric, and the cone of B (closed circle or parallel)
};
struct LabelsSpec {
  std::optional<std::vector<Fact>> facts;  // nullopt: "auto" (resolveFacts); empty: "none"
};

enum class Easing { Linear, Smooth };

// [animation]: how frame time maps to arc length, and the encoder's settings.
// The motion lasts `duration` seconds, or L/speed when `speed` is given.
struct AnimationSpec {
  FrameRate fps;                // 30/1; exact rationals for NTSC (30000/1001)
  double duration = 10.0;       // seconds for the whole path
  std::optional<double> speed;  // arc length per second (instead of duration)
  Easing easing = Easing::Smooth;
  double hold = 0.5;              // seconds the first and the last frame are held
  std::optional<double> crf;      // constant rate factor, 0 … 51; default: the format's (18 H.264, 31 VP9)
  std::string preset = "medium";  // x264 preset (WebM maps it to libvpx's cpu-used)
  bool loop = true;               // a GIF loops forever (false: plays once)
};

// A camera change: render's camera keys, each optional (absent = unchanged).
struct CameraSpec {
  std::optional<double> azimuthDeg, elevationDeg, distance, fovDeg;
  std::optional<Vec3> target;
  std::optional<bool> follow;
};

// [[segment]]: one step of a storyboard (docs/scenes.md#storyboards): a motion
// along its own path, or a hold; with its caption, title and camera.
struct SegmentSpec {
  std::optional<PathSpec> path;      // a motion; absent: a hold
  double hold = 0.0;                 // a hold: seconds the ball rests
  std::optional<double> duration;    // a motion: seconds
  std::optional<double> speed;       // a motion: arc length per second (instead of duration)
  std::string caption;               // shown while the segment plays ("" = none)
  std::optional<std::string> title;  // replaces render.title while the segment plays
  CameraSpec camera;                 // laid over the previous segment's camera (the first: over [render])
  // A motion's own surface (docs/scenes.md#surfaces-per-segment); absent: the
  // previous segment's (the first: [surface]). Where it changes, the clip
  // cuts, or cross-fades over fadeSeconds.
  std::optional<SurfaceSpec> surface;
  enum class Transition { Cut, Fade } transition = Transition::Cut;
  double fadeSeconds = 0.5;
};
inline constexpr std::size_t kMaxSegments = 1000;

struct SceneSpec {
  std::string sourceFile;  // the scene file ("" when built in code)
  std::string name;        // file stem, e.g. "lollipop"
  BallSpec ball;
  SurfaceSpec surface;
  PathSpec path;
  std::optional<PlateSpec> plate;  // [plate] present: Brockett's upper plate
  SolverSpec solver;
  TimelineSpec timeline;
  RenderSpec render;
  FigureSpec figure;
  LabelsSpec labels;
  AnimationSpec animation;
  std::vector<SegmentSpec> segments;  // a storyboard: non-empty, and `path` is unused

  [[nodiscard]] bool isStoryboard() const { return !segments.empty(); }
  // "segment[k]" (k counts from 1), the prefix of segment k's keys.
  [[nodiscard]] static std::string segmentKey(std::size_t index) {
    return "segment[" + std::to_string(index + 1) + "]";
  }
  // The surface segment `index` rolls on (its own, else the last one a
  // segment before it gave, else [surface]) and its index among the scene's
  // surfaces (0: [surface], or the first segment's own); surfaceCount() ≥ 1.
  [[nodiscard]] const SurfaceSpec& surfaceOf(std::size_t index) const;
  [[nodiscard]] std::size_t surfaceIndexOf(std::size_t index) const;
  [[nodiscard]] std::size_t surfaceCount() const;
  // The key of the table that gave segment `index`'s surface ("surface",
  // "segment[3].surface").
  [[nodiscard]] std::string surfaceKeyOf(std::size_t index) const;

  // Where a dotted key ("ball.radius", "segment[2].path.radius") was set; the file (no line) when the
  // key took its default.
  [[nodiscard]] SourceLoc where(const std::string& key) const;
  std::map<std::string, SourceLoc> locations;
};

// Which kind-specific keys apply (from the kind tables, surface_kinds.hpp
// and path_kinds.hpp): the loader rejects the others, and the scene printer
// prints exactly these. `kinds` says where a key applies, for messages.
struct KeyRule {
  bool applies = true;
  std::string kinds;
};
[[nodiscard]] KeyRule surfaceKeyRule(const std::string& key, SurfaceKind sk);
[[nodiscard]] KeyRule pathKeyRule(const std::string& key, PathKind pk, SurfaceKind sk);

[[nodiscard]] std::string toString(SurfaceKind k);
[[nodiscard]] std::string toString(PathKind k);
[[nodiscard]] std::string toString(RenderLayout l);

inline const std::vector<std::string> kFactNames{"delta", "marks", "turns", "phase-split"};
[[nodiscard]] std::string toString(Fact f);
// Whether fact f has a meaning (and a closed form) for the scene's kinds.
[[nodiscard]] KeyRule factRule(Fact f, const SceneSpec& spec);
// The facts a scene shows: labels.facts as given, or for "auto" its kind's:
// Brockett's plate → marks; another circle on a plane → delta; a parallel on
// a sphere → turns at the equator, phase-split for a small ball (R ≤ r/10,
// whole circuits), delta otherwise; any other path → none.
[[nodiscard]] std::vector<Fact> resolveFacts(const SceneSpec& spec);

}  // namespace rollspin::scene
