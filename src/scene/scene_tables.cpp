// The section tables. A new key is one row here: its field binding makes the
// loader read and check it, `scene --print` write it and `rollspin keys`
// list it. Rows are in the reference's order; printOrder places a row where
// `scene --print` has always shown it.
#include "scene/scene_tables.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "media/output_format.hpp"
#include "render/gl_context.hpp"
#include "spin/propagator.hpp"

// The tables keep one row per key as written, each row's fields wrapped by
// hand; clang-format would put every field of a row on a line of its own
// (the file would double and the tables stop reading as tables).
// clang-format off
namespace rollspin::scene {

namespace key {
const std::string_view kRadius = "radius", kMethod = "method", kSteps = "steps", kTolerance = "tolerance";
const std::string_view kWidth = "width", kHeight = "height", kTransparent = "transparent", kTitle = "title", kTarget = "target",
                       kFollow = "follow", kDistance = "distance", kFormat = "format", kBackend = "backend", kDevice = "device",
                       kMsaa = "msaa";
const std::string_view kWidthMm = "width_mm", kWidthIn = "width_in", kFontSizePt = "font_size_pt";
const std::string_view kFacts = "facts", kLabels = "labels";
const std::string_view kFps = "fps", kDuration = "duration", kSpeed = "speed", kHold = "hold";
const std::string_view kLength = "length", kDirectionVector = "direction_vector", kTurns = "turns", kDirection =
    "direction", kStartAzimuthDeg = "start_azimuth_deg", kColatitudeDeg = "colatitude_deg", kTubeAngleDeg =
    "tube_angle_deg", kAzimuthDeg = "azimuth_deg", kColatitudeStartDeg = "colatitude_start_deg",
    kColatitudeEndDeg = "colatitude_end_deg", kPitchAngleDeg = "pitch_angle_deg", kHeadingDeg = "heading_deg",
    kStartPoint = "start_point", kU = "u", kV = "v", kTStart = "t_start", kTEnd = "t_end", kPoints = "points",
    kClosed = "closed", kInterpolation = "interpolation", kCornerRadius = "corner_radius", kCurvatureStart =
    "curvature_start", kCurvatureRate = "curvature_rate";
const std::string_view kPath = "path", kSurface = "surface", kCamera = "camera", kCaption = "caption",
                       kTransition = "transition", kFadeSeconds = "fade_seconds";
}  // namespace key

std::string tomlQuoted(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

namespace {

Bounds tableAbove(double lo) { return {lo, std::nullopt, true, false}; }
Bounds tableAtLeast(double lo) { return {lo, std::nullopt, false, false}; }
Bounds tableClosed(double lo, double hi) { return {lo, hi, false, false}; }
Bounds tableOpen(double lo, double hi) { return {lo, hi, true, true}; }
Bounds tableLeftOpen(double lo, double hi) { return {lo, hi, true, false}; }

// The camera keys of [render] (plain fields with defaults) and of a
// segment's camera table (optional fields: absent = the previous segment's).
template <class S>
struct CameraFields {
  FieldOf<S> azimuth, elevation, distance, target, follow, fov;
};

template <class S>
KeyTable<S> cameraRows(const CameraFields<S>& f, bool segment, int printOrder) {
  const std::string previous = segment ? "the previous segment's" : "";
  auto dflt = [&](const std::string& own) { return segment ? previous : own; };
  auto at = [&](int k) { return printOrder < 0 ? -1 : printOrder + k; };
  return {
      {.name = "azimuth_deg", .type = "number", .field = f.azimuth, .defaultText = previous, .units = "degrees",
       .meaning = "the camera's azimuth about the target", .printOrder = at(0)},
      {.name = "elevation_deg", .type = "number", .field = f.elevation, .bounds = tableOpen(-90, 90),
       .noun = "an elevation", .unitWord = "degrees", .defaultText = previous, .units = "degrees",
       .meaning = "the camera's elevation above the horizon", .printOrder = at(1)},
      {.name = key::kDistance, .type = "number", .field = f.distance, .bounds = tableAbove(0),
       .noun = "a camera distance", .defaultText = dflt("frames the whole path"), .units = "length",
       .meaning = "the camera's distance from the target", .unsetNote = segment ? "" : "framed automatically",
       .printOrder = at(2)},
      {.name = key::kTarget, .type = "[x, y, z]", .field = f.target, .defaultText = dflt("the path's centre"),
       .units = "length", .meaning = "the point the camera looks at",
       .unsetNote = segment ? "" : "framed automatically", .printOrder = at(3)},
      {.name = key::kFollow, .type = "boolean", .field = f.follow, .defaultText = previous,
       .meaning = "the camera follows the ball", .printOrder = at(4)},
      {.name = "fov_deg", .type = "number", .field = f.fov, .bounds = tableClosed(kMinFovDeg, kMaxFovDeg),
       .noun = "a vertical field of view", .unitWord = "degrees", .defaultText = previous, .units = "degrees",
       .meaning = "the vertical field of view", .printOrder = at(5)},
  };
}

}  // namespace

const KeyTable<BallSpec>& ballKeys() {
  static const KeyTable<BallSpec> rows{
      {.name = key::kRadius, .type = "number", .field = &BallSpec::radius, .bounds = tableAbove(0), .noun = "a radius",
       .units = "length", .meaning = "the ball's radius R"},
      {.name = "texture", .type = "string", .field = &BallSpec::texture, .noun = "a PNG or JPG file name",
       .defaultText = "the built-in tennis ball", .rangeNote = "non-empty",
       .meaning = "an equirectangular PNG/JPG painted on the ball (relative to the scene file)",
       .unsetNote = "the built-in tennis ball"},
      {.name = "marker", .type = "[x, y, z]", .field = &BallSpec::marker,
       .noun = "a non-zero vector (a direction in the ball)", .defaultText = "the top n(0)",
       .rangeNote = "non-zero; normalised", .meaning = "the body direction whose trail is the tracked Bloch vector",
       .unsetNote = "the top of the ball at s = 0"},
  };
  return rows;
}

// [plate]: its one key is required, so rule code reads it (Reader::read).
const KeyTable<PlateSpec>& plateKeys() {
  static const KeyTable<PlateSpec> rows{
      {.name = key::kRadius, .type = "number", .field = &PlateSpec::radius, .bounds = tableAbove(0),
       .noun = "a radius", .defaultText = "(required)", .units = "length",
       .meaning = "Brockett's plate: the radius R1 of the circle each plate point describes", .byRule = true},
  };
  return rows;
}

// [path], and a segment's path: which keys apply to which kinds is the path
// kind table's (path_kinds.cpp, through these constants). Rows the rule
// code reads: a direction in the plane, the expressions, the points.
const KeyTable<PathSpec>& pathKeys() {
  static const KeyTable<PathSpec> rows = [] {
    const PathSpec d;
    const ChoiceField<PathSpec> direction{[](const PathSpec& p) { return std::size_t(p.counterClockwise ? 0 : 1); },
                                          [](PathSpec& p, std::size_t i) { p.counterClockwise = i == 0; }};
    const std::string heading = fmt::format(
        "a heading in (-{0}, {0}) degrees from the meridians ({0} is a parallel: use kind = \"parallel\")", 90);
    const std::string curvature = fmt::format("|value| <= 1e{}", int(std::lround(std::log10(kMaxCurvature))));
    return KeyTable<PathSpec>{
        {.name = key::kLength, .type = "number", .field = &PathSpec::length, .bounds = tableAbove(0),
         .noun = "a length", .defaultText = tomlNumber(d.length) + " (geodesic: 6)", .units = "length",
         .meaning = "the arc length travelled"},
        {.name = key::kDirectionVector, .type = "[x, y, z]", .field = &PathSpec::directionVector,
         .noun = "a non-zero vector", .defaultText = "horizontal in the plane",
         .rangeNote = "non-zero; in the plane on a plane", .meaning = "the start heading", .byRule = true},
        {.name = key::kTurns, .type = "number", .field = &PathSpec::turns, .bounds = tableAbove(0),
         .noun = "a number of turns", .units = "turns", .meaning = "how many times round"},
        {.name = key::kDirection, .type = "string", .field = direction, .choices = {"ccw", "cw"},
         .meaning = "the sense of rotation, seen from the normal's side"},
        {.name = key::kRadius, .type = "number", .field = &PathSpec::radius, .bounds = tableAbove(0),
         .noun = "a radius", .defaultText = tomlNumber(d.radius) + " (paraboloid parallel: 2)", .units = "length",
         .meaning = "circle: the contact circle's radius; paraboloid parallel: its radius"},
        {.name = key::kStartAzimuthDeg, .type = "number", .field = &PathSpec::startAzimuthDeg, .units = "degrees",
         .meaning = "the azimuth a parallel starts at (0: see Conventions)"},
        {.name = key::kColatitudeDeg, .type = "number", .field = &PathSpec::colatitudeDeg, .bounds = tableOpen(0, 180),
         .noun = "a colatitude", .unitWord = "degrees", .units = "degrees",
         .meaning = "the parallel's colatitude θ on a sphere"},
        {.name = key::kTubeAngleDeg, .type = "number", .field = &PathSpec::tubeAngleDeg, .units = "degrees",
         .meaning = "the angle ψ up the torus tube (0 = outer equator)"},
        {.name = key::kHeight, .type = "number", .field = &PathSpec::height, .units = "length",
         .meaning = "the start height along the cylinder's axis"},
        {.name = key::kAzimuthDeg, .type = "number", .field = &PathSpec::azimuthDeg, .units = "degrees",
         .meaning = "the start azimuth φ0"},
        {.name = key::kColatitudeStartDeg, .type = "number", .field = &PathSpec::colatitudeStartDeg,
         .bounds = tableOpen(0, 180), .noun = "a colatitude", .unitWord = "degrees", .units = "degrees",
         .meaning = "the start colatitude θ0"},
        {.name = key::kColatitudeEndDeg, .type = "number", .field = &PathSpec::colatitudeEndDeg,
         .bounds = tableOpen(0, 180), .noun = "a colatitude", .unitWord = "degrees",
         .rangeNote = "!= colatitude_start_deg", .units = "degrees", .meaning = "the end colatitude θ1"},
        {.name = key::kPitchAngleDeg, .type = "number", .field = &PathSpec::pitchAngleDeg, .bounds = tableOpen(-90, 90),
         .noun = "a pitch angle", .unitWord = "degrees", .units = "degrees",
         .meaning = "the helix's angle β from the parallels"},
        {.name = key::kHeadingDeg, .type = "number", .field = &PathSpec::headingDeg, .bounds = tableOpen(-90, 90),
         .expected = heading, .units = "degrees", .meaning = "the loxodrome's heading α from the meridians"},
        // Printed by writePath: its computed default depends on where the path starts.
        {.name = key::kStartPoint, .type = "[x, y, z]", .field = &PathSpec::startPoint, .defaultText = "per surface",
         .units = "length", .meaning = "the geodesic's start, projected onto the surface"},
        {.name = key::kU, .type = "expression", .field = &PathSpec::u, .rangeNote = "muparser syntax in t",
         .meaning = "the first surface parameter as a function of t", .byRule = true},
        {.name = key::kV, .type = "expression", .field = &PathSpec::v, .rangeNote = "muparser syntax in t",
         .meaning = "the second surface parameter as a function of t", .byRule = true},
        {.name = key::kTStart, .type = "number", .field = &PathSpec::tStart, .meaning = "where t starts"},
        {.name = key::kTEnd, .type = "number", .field = &PathSpec::tEnd, .rangeNote = "> t_start",
         .meaning = "where t ends"},
        {.name = key::kPoints, .type = "array of [u, v] or [x, y, z]", .defaultText = "(required)",
         .rangeNote = "at least 2 points (3 when closed)", .meaning = "the points the path passes through",
         .byRule = true, .printText = [](const PathSpec& p) -> std::optional<std::string> {
           std::string list = "[";
           for (std::size_t i = 0; i < p.points.size(); ++i) {
             list += i ? ", [" : "[";
             for (std::size_t j = 0; j < p.points[i].size(); ++j) list += (j ? ", " : "") + tomlNumber(p.points[i][j]);
             list += "]";
           }
           return list + "]";
         }},
        {.name = key::kClosed, .type = "boolean", .field = &PathSpec::closed,
         .meaning = "a periodic spline or a closed polygon"},
        {.name = key::kInterpolation, .type = "string", .field = &PathSpec::interpolation,
         .choices = {"spline", "polyline"}, .meaning = "a cubic spline through the points, or straight pieces"},
        {.name = key::kCornerRadius, .type = "number", .field = &PathSpec::cornerRadius, .bounds = tableAtLeast(0),
         .noun = "a radius", .units = "length", .meaning = "a polyline's corners rounded by arcs of this radius"},
        {.name = key::kCurvatureStart, .type = "number", .field = &PathSpec::curvatureStart,
         .bounds = tableClosed(-kMaxCurvature, kMaxCurvature), .expected = curvature, .units = "1/length",
         .meaning = "the clothoid's geodesic curvature κ₀ at s = 0"},
        {.name = key::kCurvatureRate, .type = "number", .field = &PathSpec::curvatureRate,
         .bounds = tableClosed(-kMaxCurvature, kMaxCurvature), .expected = curvature, .units = "1/length²",
         .meaning = "α in κ_g = κ₀ + α s"},
    };
  }();
  return rows;
}

const KeyTable<SolverSpec>& solverKeys() {
  static const KeyTable<SolverSpec> rows = [] {
    std::vector<std::string> methods;
    for (spin::Method m : spin::allMethods()) methods.emplace_back(spin::methodName(m));
    const SolverSpec d;
    return KeyTable<SolverSpec>{
        {.name = key::kMethod, .type = "string", .field = &SolverSpec::method, .choices = methods,
         .defaultText = tomlQuoted(d.method) + " (frame6a with only a tolerance)", .meaning = "the propagator"},
        {.name = key::kSteps, .type = "integer", .field = &SolverSpec::steps,
         .bounds = tableClosed(1, double(kMaxSolverSteps)), .noun = "an integer", .defaultText = "automatic",
         .rangeNote = "fixed-step methods only", .meaning = "the number of steps", .unsetNote = "automatic"},
        {.name = key::kTolerance, .type = "number", .field = &SolverSpec::tolerance, .bounds = tableClosed(1e-15, 1),
         .noun = "a tolerance", .defaultText = tomlNumber(SolverSpec::kDefaultTolerance),
         .rangeNote = "adaptive methods only", .meaning = "the adaptive methods' error per unit length"},
        // Printed only when off: the resolved text (and the hash of it in a
        // video's metadata) of every scene that keeps the default stays as it was.
        {.name = "error_estimate", .type = "boolean", .field = &SolverSpec::errorEstimate,
         .defaultText = tomlBool(d.errorEstimate),
         .meaning = "the a posteriori error estimate of U(L), a second solve (docs/solver.md); false skips it and "
                    "its cost (and automatic steps' refinement)",
         .printText = [](const SolverSpec& s) -> std::optional<std::string> {
           if (s.errorEstimate) return std::nullopt;
           return tomlBool(false);
         }},
    };
  }();
  return rows;
}

const KeyTable<TimelineSpec>& timelineKeys() {
  static const KeyTable<TimelineSpec> rows{
      {.name = "samples", .type = "integer", .field = &TimelineSpec::samples,
       .bounds = tableClosed(2, double(kMaxTimelineSamples)), .noun = "an integer", .defaultText = "60 per turn, + 1",
       .meaning = "rows of `rollspin timeline`'s CSV", .unsetNote = "60 per turn + 1"},
  };
  return rows;
}

namespace {

KeyTable<RenderSpec> buildRenderKeys() {
  std::set<std::string> formats;
  for (const media::OutputFormat& f : media::kOutputFormats) formats.emplace(f.name);
  const ChoiceField<RenderSpec> layout{[](const RenderSpec& r) { return std::size_t(r.layout); },
                                       [](RenderSpec& r, std::size_t i) { r.layout = RenderLayout(i); }};
  const ChoiceField<RenderSpec> twinCamera{[](const RenderSpec& r) { return std::size_t(r.twinCameraFixed ? 0 : 1); },
                                           [](RenderSpec& r, std::size_t i) { r.twinCameraFixed = i == 0; }};
  KeyTable<RenderSpec> rows{
      {.name = key::kWidth, .type = "integer", .field = &RenderSpec::width,
       .bounds = tableClosed(double(kMinImageSide), double(kMaxImageSide)), .noun = "an image size",
       .unitWord = "pixels", .units = "pixels", .meaning = "the image width"},
      {.name = key::kHeight, .type = "integer", .field = &RenderSpec::height,
       .bounds = tableClosed(double(kMinImageSide), double(kMaxImageSide)), .noun = "an image size",
       .unitWord = "pixels", .units = "pixels", .meaning = "the image height"},
      {.name = "layout", .type = "string", .field = layout, .choices = {"side-by-side", "inset", "ball", "twin"},
       .meaning = "the views: the scene and the Bloch sphere side by side, the sphere inset, the ball alone, or the "
                  "twin"},
      {.name = "strobe", .type = "integer", .field = &RenderSpec::strobe, .bounds = tableClosed(0, double(kMaxStrobe)),
       .expected = fmt::format("0 (off) or a number of positions in [2, {}]", kMaxStrobe),
       .accepts = [](double n) { return n == 0 || (n >= 2 && n <= double(kMaxStrobe)); },
       .rangeNote = "not 1 (0 is off)", .meaning = "the ball at N evenly spaced positions in one image"},
      {.name = key::kTitle, .type = "string", .field = &RenderSpec::title, .defaultText = "\"\" (none)",
       .meaning = "a title over the image"},
      {.name = key::kLabels, .type = "boolean", .field = &RenderSpec::labels,
       .meaning = "axis, pole and live labels (s, angles)"},
      {.name = key::kTransparent, .type = "boolean", .field = &RenderSpec::transparent,
       .meaning = "no background (PNG, WebM, MOV keep the alpha)", .printOrder = 8},
      {.name = "burn_captions", .type = "boolean", .field = &RenderSpec::burnCaptions,
       .meaning = "draw the title and the storyboard captions into the pixels (false: only the subtitle track and "
                  ".vtt carry them)",
       .printOrder = 9},
      {.name = key::kMsaa, .type = "integer", .field = &RenderSpec::msaa,
       .bounds = tableClosed(double(kMsaaSamples.front()), double(kMsaaSamples.back())),
       .expected = "1, 2 or 4 samples",
       .accepts = [](double n) { return std::find(kMsaaSamples.begin(), kMsaaSamples.end(), n) != kMsaaSamples.end(); },
       .rangeNote = "1, 2 or 4", .units = "samples", .meaning = "multisample anti-aliasing", .printOrder = 10},
  };
  for (KeyRow<RenderSpec>& row :
       cameraRows<RenderSpec>({&RenderSpec::azimuthDeg, &RenderSpec::elevationDeg, &RenderSpec::distance,
                               &RenderSpec::target, &RenderSpec::follow, &RenderSpec::fovDeg},
                              false, 11))
    rows.push_back(std::move(row));
  KeyTable<RenderSpec> rest{
      {.name = key::kFormat, .type = "string", .field = &RenderSpec::format, .choices = {formats.begin(), formats.end()},
       .defaultText = "from the output's extension, else mp4 (a clip) or png (a still)",
       .meaning = "the output format (docs/rendering.md)",
       .unsetNote = "from the output's extension, else mp4 (a still: png)", .printOrder = 19},
      {.name = "trails", .type = "boolean", .field = &RenderSpec::trails, .meaning = "the marker's and the field's trails",
       .printOrder = 6},
      {.name = "shadow", .type = "boolean", .field = &RenderSpec::shadow, .meaning = "the key light's shadow",
       .printOrder = 7},
      {.name = "dpi", .type = "number", .field = &RenderSpec::dpi, .bounds = tableClosed(kMinDpi, kMaxDpi),
       .noun = "a resolution", .unitWord = "dpi", .units = "dpi",
       .meaning = "PDF/SVG figures: the resolution of their raster parts", .printOrder = 21},
      {.name = "jpeg_quality", .type = "integer", .field = &RenderSpec::jpegQuality,
       .bounds = tableClosed(1, double(kMaxJpegQuality)), .noun = "a JPEG quality", .meaning = "JPEG stills' quality",
       .printOrder = 20},
      {.name = "font_scale", .type = "number", .field = &RenderSpec::fontScale,
       .bounds = tableClosed(kMinFontScale, kMaxFontScale), .noun = "a text scale",
       .meaning = "the text size, times this", .printOrder = 17},
      {.name = "twin_camera", .type = "string", .field = twinCamera, .choices = {"fixed", "linked"},
       .meaning = "twin layout: the first shot's view throughout, or the scene camera's", .printOrder = 18},
      {.name = key::kBackend, .type = "string", .field = &RenderSpec::backend, .choices = render::backendNames(),
       .defaultText = "ROLLSPIN_GL, else \"auto\"", .meaning = "the GL backend (docs/gl-backends.md)",
       .unsetNote = "ROLLSPIN_GL, else \"auto\"", .printOrder = 22},
      // Read by rule code (Reader::readGlContext): an index or a path.
      {.name = key::kDevice, .type = "integer or string", .defaultText = "ROLLSPIN_EGL_DEVICE",
       .rangeNote = "an EGL device index >= 0 or a DRM path \"/dev/dri/…\"", .meaning = "the GPU an EGL render uses",
       .byRule = true, .unsetNote = "ROLLSPIN_EGL_DEVICE, else the first GPU",
       .printText = [](const RenderSpec& r) -> std::optional<std::string> {
         if (!r.device) return std::nullopt;
         return r.device->front() == '/' ? tomlQuoted(*r.device) : *r.device;
       },
       .printOrder = 23},
  };
  for (KeyRow<RenderSpec>& row : rest) rows.push_back(std::move(row));
  return rows;
}

}  // namespace

const KeyTable<RenderSpec>& renderKeys() {
  static const KeyTable<RenderSpec> rows = buildRenderKeys();
  return rows;
}

// [figure]: the width is one of three keys, so rule code reads them
// (Reader::readFigure); the rows give `keys` and `scene --print` their text.
const KeyTable<FigureSpec>& figureKeys() {
  static const KeyTable<FigureSpec> rows{
      {.name = key::kWidth, .type = "string", .choices = {"column", "page"}, .defaultText = "(width_mm)",
       .rangeNote = "not with width_mm or width_in", .meaning = "a preset width: \"column\" = 85 mm, \"page\" = 175 mm",
       .byRule = true, .printed = false},
      {.name = key::kWidthMm, .type = "number", .field = &FigureSpec::widthMm,
       .bounds = tableClosed(kMinFigureWidthMm, kMaxFigureWidthMm), .units = "mm",
       .meaning = "the figure's printed width", .byRule = true},
      {.name = key::kWidthIn, .type = "number", .bounds = tableClosed(kMinFigureWidthMm / 25.4, kMaxFigureWidthMm / 25.4),
       .defaultText = "(width_mm)", .rangeNote = "not with width_mm", .units = "inches",
       .meaning = "the width in inches instead", .byRule = true, .printed = false},
      {.name = "font", .type = "string", .field = &FigureSpec::font,
       .noun = "a font family name (e.g. \"Latin Modern Roman\")", .rangeNote = "non-empty",
       .meaning = "the labels' font family (fontconfig name)"},
      {.name = key::kFontSizePt, .type = "number", .field = &FigureSpec::fontSizePt,
       .bounds = tableClosed(kMinFontSizePt, kMaxFontSizePt), .noun = "a size", .unitWord = "pt", .defaultText = "8",
       .units = "pt", .meaning = "the body text size", .unsetNote = "the still's proportions"},
      {.name = key::kTransparent, .type = "boolean", .field = &FigureSpec::transparent,
       .meaning = "a transparent page (false: the views' backdrops)"},
  };
  return rows;
}

// [labels]: a word or a list of facts, each checked against the scene's
// kinds; rule code reads it (Reader::readLabels) and prints it (writeScene).
const KeyTable<LabelsSpec>& labelsKeys() {
  static const KeyTable<LabelsSpec> rows = [] {
    std::string facts;
    for (const auto& n : kFactNames) facts += (facts.empty() ? "" : ", ") + n;
    return KeyTable<LabelsSpec>{
        {.name = key::kFacts, .type = "string or array", .defaultText = "\"auto\"",
         .rangeNote = "\"auto\", \"none\" or a list of: " + facts,
         .meaning = "which facts of the scene are printed beside the paper's closed form", .byRule = true,
         .printed = false},
    };
  }();
  return rows;
}

const KeyTable<AnimationSpec>& animationKeys() {
  static const KeyTable<AnimationSpec> rows = [] {
    const ChoiceField<AnimationSpec> easing{
        [](const AnimationSpec& a) { return std::size_t(a.easing == Easing::Smooth ? 0 : 1); },
        [](AnimationSpec& a, std::size_t i) { a.easing = i == 0 ? Easing::Smooth : Easing::Linear; }};
    return KeyTable<AnimationSpec>{
        // Read by rule code (Reader::readAnimation): an integer, a decimal or "num/den".
        {.name = key::kFps, .type = "number or string", .bounds = tableClosed(kMinFps, kMaxFps),
         .rangeNote = "an integer, 23.976 | 29.97 | 59.94, or \"num/den\"", .units = "1/s",
         .meaning = "frames per second", .byRule = true,
         .printText = [](const AnimationSpec& a) -> std::optional<std::string> {
           return a.fps.den == 1 ? a.fps.text() : tomlQuoted(a.fps.text());
         }},
        // The speed, when given, replaces the duration in the printed scene.
        {.name = key::kDuration, .type = "number", .field = &AnimationSpec::duration,
         .bounds = tableLeftOpen(0, kMaxDurationSeconds), .noun = "a duration", .unitWord = "seconds",
         .units = "seconds", .meaning = "how long the whole path takes",
         .printText = [](const AnimationSpec& a) -> std::optional<std::string> {
           if (a.speed) return std::nullopt;
           return tomlNumber(a.duration);
         },
         .printOrder = 2},
        {.name = key::kSpeed, .type = "number", .field = &AnimationSpec::speed, .bounds = tableAbove(0),
         .noun = "an arc length per second", .defaultText = "(duration)", .rangeNote = "not with duration",
         .units = "length/s", .meaning = "arc length per second instead of a duration", .printOrder = 1},
        {.name = "easing", .type = "string", .field = easing, .choices = {"smooth", "linear"},
         .meaning = "ease in and out, or a constant speed"},
        {.name = key::kHold, .type = "number", .field = &AnimationSpec::hold,
         .bounds = tableClosed(0, kMaxHoldSeconds), .noun = "a hold", .unitWord = "seconds", .units = "seconds",
         .meaning = "how long the first and the last frame are held"},
        {.name = "crf", .type = "number", .field = &AnimationSpec::crf, .bounds = tableClosed(0, kMaxCrf),
         .noun = "a CRF", .defaultText = "the format's (18 H.264, 31 VP9)",
         .meaning = "the encoder's constant rate factor (lower: better)",
         .unsetNote = "the format's: 18 for mp4 (H.264), 31 for webm (VP9)"},
        {.name = "preset", .type = "string", .field = &AnimationSpec::preset,
         .choices = {"ultrafast", "superfast", "veryfast", "faster", "fast", "medium", "slow", "slower", "veryslow"},
         .meaning = "the x264 preset (WebM maps it to libvpx's cpu-used)"},
        {.name = "loop", .type = "boolean", .field = &AnimationSpec::loop,
         .meaning = "a GIF loops forever (false: plays once)"},
    };
  }();
  return rows;
}

// [[segment]]: whether a segment moves or holds decides which keys apply,
// so rule code reads them (Reader::readSegments) through these rows' checks
// and writeSegments prints them.
const KeyTable<SegmentSpec>& segmentKeys() {
  static const KeyTable<SegmentSpec> rows = [] {
    const ChoiceField<SegmentSpec> transition{
        [](const SegmentSpec& s) { return std::size_t(s.transition == SegmentSpec::Transition::Fade ? 1 : 0); },
        [](SegmentSpec& s, std::size_t i) {
          s.transition = i == 1 ? SegmentSpec::Transition::Fade : SegmentSpec::Transition::Cut;
        }};
    return KeyTable<SegmentSpec>{
        {.name = key::kPath, .type = "table", .defaultText = "(a hold)", .rangeNote = "the [path] keys",
         .meaning = "the segment's motion: path = { kind = ..., ... }", .byRule = true},
        {.name = key::kHold, .type = "number", .field = &SegmentSpec::hold,
         .bounds = tableLeftOpen(0, kMaxHoldSeconds), .noun = "a hold", .unitWord = "seconds",
         .defaultText = "(a motion)", .rangeNote = "not with path", .units = "seconds",
         .meaning = "the ball rests this long", .byRule = true},
        {.name = key::kDuration, .type = "number", .field = &SegmentSpec::duration,
         .bounds = tableLeftOpen(0, kMaxDurationSeconds), .noun = "a duration", .unitWord = "seconds",
         .defaultText = "the motion's share of animation.duration", .rangeNote = "with path only",
         .units = "seconds", .meaning = "how long the motion takes", .byRule = true},
        {.name = key::kSpeed, .type = "number", .field = &SegmentSpec::speed, .bounds = tableAbove(0),
         .noun = "an arc length per second", .defaultText = "(duration)",
         .rangeNote = "with path only; not with duration", .units = "length/s",
         .meaning = "arc length per second instead of a duration", .byRule = true},
        {.name = key::kCaption, .type = "string", .field = &SegmentSpec::caption,
         .meaning = "the caption shown while the segment plays", .byRule = true},
        {.name = key::kTitle, .type = "string", .field = &SegmentSpec::title, .defaultText = "render.title",
         .meaning = "replaces render.title while the segment plays", .byRule = true},
        {.name = key::kSurface, .type = "table", .defaultText = "the previous segment's ([surface] for the first)",
         .rangeNote = "the [surface] keys; with path only",
         .meaning = "the surface this motion rolls on: surface = { kind = ..., ... }; a change cuts the clip",
         .byRule = true},
        {.name = key::kTransition, .type = "string", .field = transition, .choices = {"cut", "fade"},
         .rangeNote = "where the surface changes", .meaning = "how the clip passes to the new surface's view",
         .byRule = true},
        {.name = key::kFadeSeconds, .type = "number", .field = &SegmentSpec::fadeSeconds,
         .bounds = tableLeftOpen(0, kMaxFadeSeconds), .noun = "a fade", .unitWord = "seconds",
         .rangeNote = "with transition = \"fade\"", .units = "seconds",
         .meaning = "how long the cross-fade to the new surface's view takes", .byRule = true},
        {.name = key::kCamera, .type = "table", .defaultText = "(unchanged)", .rangeNote = "the segment.camera keys",
         .meaning = "a camera change laid over the previous segment's", .byRule = true},
    };
  }();
  return rows;
}

const KeyTable<CameraSpec>& segmentCameraKeys() {
  static const KeyTable<CameraSpec> rows =
      cameraRows<CameraSpec>({&CameraSpec::azimuthDeg, &CameraSpec::elevationDeg, &CameraSpec::distance,
                              &CameraSpec::target, &CameraSpec::follow, &CameraSpec::fovDeg},
                             true, -1);
  return rows;
}

}  // namespace rollspin::scene
// clang-format on
