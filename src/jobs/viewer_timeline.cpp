#include "jobs/viewer_timeline.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "jobs/timeline_csv.hpp"
#include "motion/frame_sampling.hpp"
#include "motion/surface_stretches.hpp"
#include "spin/field.hpp"

namespace rollspin::jobs {

namespace {

// Where |B| is probed to choose the spacing.
constexpr int kFieldProbes = 4000;

// The fastest the spinor turns or its field swings along the path, as a
// rate per unit arc length: |B| + 2√|dB/ds| (a clothoid's field keeps its
// size but turns ever faster), probed on a fine grid (dB/ds by differences
// between neighbours) and at both sides of each break.
double largestFieldRate(const model::RollingModel& model, const std::vector<double>& breaks) {
  const double length = model.path->length(), R = model.ballRadius;
  auto field = [&](double s) { return spin::fieldB(model.path->at(std::clamp(s, 0.0, length)), R); };
  double largest = 0.0;
  const double ds = length / kFieldProbes;
  geometry::Vec3 previous = field(0.0);
  for (int k = 1; k <= kFieldProbes; ++k) {
    const geometry::Vec3 b = field(k * ds);
    // A difference across a break is a jump, not a rate: the knots land on breaks.
    const bool acrossBreak =
        std::any_of(breaks.begin(), breaks.end(), [&](double x) { return x > (k - 1) * ds && x <= k * ds; });
    const double swing = acrossBreak ? 0.0 : 2.0 * std::sqrt((b - previous).norm() / ds);
    largest = std::max(largest, b.norm() + swing);
    previous = b;
  }
  for (const double b : breaks) largest = std::max({largest, field(b).norm(), field(b - kTwinKnotGap * length).norm()});
  return largest;
}

// A storyboard's joins and the path's own breakpoints, inside (0, L), sorted, unique.
std::vector<double> interiorBreaks(const model::RollingModel& model) {
  const double length = model.path->length();
  std::vector<double> breaks = model.path->breakpoints();
  for (const model::SegmentSpan& span : model.segments) breaks.insert(breaks.end(), {span.start, span.end});
  std::erase_if(breaks, [&](double b) { return !(b > 0.0 && b < length); });
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  return breaks;
}

// The surface stretch of each scene segment (all 0 for one surface).
std::vector<std::size_t> segmentStretches(const scene::SceneSpec& spec, const model::RollingModel& model) {
  std::vector<std::size_t> out(spec.segments.size(), 0);
  const std::vector<motion::SurfaceStretch> stretches = motion::surfaceStretches(spec, model);
  for (std::size_t k = 0; k < stretches.size(); ++k)
    for (std::size_t seg = stretches[k].firstSegment; seg < stretches[k].endSegment && seg < out.size(); ++seg)
      out[seg] = k;
  return out;
}

// The frame clock's pieces (FrameClock::motionBounds), in seconds.
ViewerClock viewerClock(const scene::SceneSpec& spec, const model::RollingModel& model,
                        const std::vector<std::size_t>& stretchOfSegment) {
  const motion::FrameClock clock = motion::clipClock(spec, model);
  const double fps = clock.fps().value(), length = model.path->length();
  const std::vector<double> bounds = clock.motionBounds();
  ViewerClock out;
  out.smooth = spec.animation.easing == scene::Easing::Smooth;
  for (const double f : bounds) out.seconds.push_back(f / fps);
  for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
    double s0 = clock.arcLengthAt(bounds[k]), s1 = clock.arcLengthAt(bounds[k + 1]);
    const auto middle = static_cast<long long>(std::floor(0.5 * (bounds[k] + bounds[k + 1])));
    const std::size_t held = clock.place(middle).segment;
    const bool hold = !(s1 > s0);
    if (hold && held < stretchOfSegment.size() &&
        stretchOfSegment[held] != stretchOfSegment[motion::storyPlaceAt(model, s0).segment])
      s0 = s1 = std::max(0.0, s0 - kTwinKnotGap * length);
    out.s0.push_back(s0);
    out.s1.push_back(s1);
    out.segment.push_back(held);
  }
  return out;
}

std::string quoted(const std::string& text) {
  // JSON inside an HTML <script>: '<' as \u003c, so no "</script>" can end it early.
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += {'\\', c};
    else if (c == '<' || static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", int(c));
    else out += c;
  }
  return out + "\"";
}

}  // namespace

std::vector<double> viewerKnotArcLengths(const model::RollingModel& model) {
  const double length = model.path->length();
  const std::vector<double> breaks = interiorBreaks(model);
  const double rate = largestFieldRate(model, breaks);
  const double step = std::min(length / double(kViewerLeastKnots), rate > 0.0 ? kViewerKnotRadians / rate : length);
  std::vector<double> knots;
  // Each stretch between breaks gets uniform knots; a break gets its twin just before it.
  double from = 0.0;
  for (std::size_t k = 0; k <= breaks.size(); ++k) {
    const double to = k < breaks.size() ? breaks[k] : length;
    const auto count = static_cast<std::size_t>(std::max(1.0, std::ceil((to - from) / step)));
    for (std::size_t j = 0; j < count; ++j) knots.push_back(from + (to - from) * double(j) / double(count));
    if (k < breaks.size() && to - kTwinKnotGap * length > knots.back()) knots.push_back(to - kTwinKnotGap * length);
    from = to;
  }
  knots.push_back(length);
  return knots;
}

ViewerTimeline sampleViewerTimeline(const scene::SceneSpec& spec, const model::RollingModel& model,
                                    const motion::SolverChoice& choice) {
  ViewerTimeline timeline;
  timeline.length = model.path->length();
  timeline.ballRadius = model.ballRadius;
  const double R = model.ballRadius;
  // The Bloch vector is the image of the marker (the renders' twin view): ball.marker, else n(0).
  geometry::Vec3 marker = spec.ball.marker
                              ? geometry::Vec3((*spec.ball.marker)[0], (*spec.ball.marker)[1], (*spec.ball.marker)[2])
                              : model.path->at(0.0).normal;
  marker.normalize();
  timeline.marker = {marker.x(), marker.y(), marker.z()};
  timeline.viewDeg = {spec.render.azimuthDeg, spec.render.elevationDeg};
  const std::vector<double> arcs = viewerKnotArcLengths(model);
  timeline.knots.resize(arcs.size());
  sampleTimeline(
      model, choice, spin::SampleArcLengths(arcs),
      [&](std::size_t index, const TimelineRow& row) {
        const auto& v = row.values;  // kTimelineColumns
        const geometry::Vec3 t(v[17], v[18], v[19]), n(v[4], v[5], v[6]), u = n.cross(t);
        const geometry::Vec3 rate = (1.0 - v[20] * R) * t - R * v[22] * u;
        timeline.knots[index] = {v[0],
                                 {v[10], v[11], v[12], v[13]},
                                 {v[14], v[15], v[16]},
                                 {v[7], v[8], v[9]},
                                 {rate.x(), rate.y(), rate.z()}};
      },
      spec.sourceFile.empty() ? spec.name : spec.sourceFile);
  const std::vector<std::size_t> stretchOfSegment = segmentStretches(spec, model);
  std::array<double, 2> view = timeline.viewDeg;
  for (std::size_t k = 0; k < spec.segments.size() && k < model.segments.size(); ++k) {
    const scene::SegmentSpec& seg = spec.segments[k];
    view = {seg.camera.azimuthDeg.value_or(view[0]), seg.camera.elevationDeg.value_or(view[1])};
    timeline.chapters.push_back({k + 1, model.segments[k].start, model.segments[k].end, seg.caption,
                                 seg.title.value_or(spec.render.title), stretchOfSegment[k], view});
  }
  timeline.clock = viewerClock(spec, model, stretchOfSegment);
  return timeline;
}

std::string viewerTimelineJson(const ViewerTimeline& timeline) {
  // Columns, not rows: one array per quantity, flat, in full precision.
  std::vector<double> s, q, b, c, dc;
  for (const ViewerKnot& k : timeline.knots) {
    s.push_back(k.s);
    q.insert(q.end(), k.q.begin(), k.q.end());
    b.insert(b.end(), k.b.begin(), k.b.end());
    c.insert(c.end(), k.centre.begin(), k.centre.end());
    dc.insert(dc.end(), k.centreRate.begin(), k.centreRate.end());
  }
  std::string chapters;
  for (const ViewerChapter& ch : timeline.chapters)
    chapters += fmt::format(
        "{}{{\"number\": {}, \"start\": {:.17g}, \"end\": {:.17g}, \"caption\": {}, \"title\": {}, "
        "\"surface\": {}, \"viewDeg\": [{:.17g}]}}",
        chapters.empty() ? "" : ", ", ch.number, ch.start, ch.end, quoted(ch.caption), quoted(ch.title), ch.surface,
        fmt::join(ch.viewDeg, ", "));
  const ViewerClock& clock = timeline.clock;
  const std::string clockJson =
      fmt::format("{{\"seconds\": [{:.17g}], \"s0\": [{:.17g}], \"s1\": [{:.17g}], \"segment\": [{}], \"smooth\": {}}}",
                  fmt::join(clock.seconds, ","), fmt::join(clock.s0, ","), fmt::join(clock.s1, ","),
                  fmt::join(clock.segment, ","), clock.smooth);
  return fmt::format(
      "{{\"length\": {:.17g}, \"ballRadius\": {:.17g}, \"marker\": [{:.17g}], \"viewDeg\": "
      "[{:.17g}], \"chapters\": [{}],\n\"clock\": {},\n"
      "\"s\": [{:.17g}],\n\"q\": [{:.17g}],\n\"B\": [{:.17g}],\n\"centre\": [{:.17g}],\n\"centreRate\": [{:.17g}]}}",
      timeline.length, timeline.ballRadius, fmt::join(timeline.marker, ", "), fmt::join(timeline.viewDeg, ", "),
      chapters, clockJson, fmt::join(s, ","), fmt::join(q, ","), fmt::join(b, ","), fmt::join(c, ","),
      fmt::join(dc, ","));
}

}  // namespace rollspin::jobs
