#include "scene/scene_writer.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "scene/scene_tables.hpp"

namespace rollspin::scene {

namespace {

std::string quoted(const std::string& s) { return tomlQuoted(s); }

// Shortest text that reads back as the same double (fmt's default).
std::string number(double v) { return tomlNumber(v); }
std::string vec(const Vec3& v) { return tomlVector(v); }

class Writer {
 public:
  explicit Writer(const std::map<std::string, std::string>& notes) : notes_(notes) {}

  void section(const std::string& name) { header("[" + name + "]", name); }
  // A header line ("[segment.path]", "[[segment]]") whose keys' notes are
  // looked up under `noteKey` ("segment[2].path"); a note on noteKey itself
  // becomes a comment above the header.
  void header(const std::string& line, const std::string& noteKey) {
    section_ = noteKey;
    if (!out_.empty()) out_ += '\n';
    if (auto it = notes_.find(noteKey); it != notes_.end()) out_ += "# " + it->second + "\n";
    out_ += line + "\n";
  }
  void key(const std::string& key, const std::string& value) {
    const std::string full = section_ + "." + key;
    std::string line = key + " = " + value;
    if (auto it = notes_.find(full); it != notes_.end()) line += "  # " + it->second;
    out_ += line + "\n";
  }
  // A key whose default is computed: a comment, unless the scene set it.
  void computed(const std::string& key, const std::string& fallback) {
    const std::string full = section_ + "." + key;
    auto it = notes_.find(full);
    out_ += "# " + key + " = " + (it != notes_.end() ? it->second : fallback) + "\n";
  }
  [[nodiscard]] const std::string& text() const { return out_; }

 private:
  const std::map<std::string, std::string>& notes_;
  std::string section_;
  std::string out_;
};

// A table's printed rows, in `scene --print`'s order: a row's printOrder
// where it has one, else its place in the table.
template <class S>
void writeKeys(Writer& w, const KeyTable<S>& rows, const S& s) {
  std::vector<std::pair<int, const KeyRow<S>*>> order;
  for (std::size_t i = 0; i < rows.size(); ++i)
    order.emplace_back(rows[i].printOrder >= 0 ? rows[i].printOrder : int(i), &rows[i]);
  std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& entry : order) {
    const KeyRow<S>& row = *entry.second;
    if (!row.printed) continue;
    const std::string name(row.name);
    if (auto text = printedValue(row, s)) w.key(name, *text);
    else if (!row.unsetNote.empty()) w.computed(name, row.unsetNote);
  }
}

std::string pathKindName(PathKind k) { return toString(k); }

// How a path's unset placement keys are resolved: by the surface (a scene's
// [path], a storyboard's first segment) or by the previous segment's end.
enum class PathDefaults { Own, FromPrevious };

void writePath(Writer& w, const PathSpec& p, SurfaceKind sk, bool plate, PathDefaults defaults) {
  const PathKind pk = p.kind;
  w.key("kind", quoted(pathKindName(pk)));
  for (const auto& key : allPathKeys()) {
    if (!pathKeyRule(key, pk, sk).applies) continue;
    // With [plate] the circle's radius is derived, and setting it is an error.
    if (key == key::kRadius && plate) continue;
    // Unset placements: the surface's default start, or the previous segment's end.
    if (key == key::kDirectionVector && !p.directionVector) {
      if (defaults == PathDefaults::Own) w.computed(key, "the default direction on this surface");
      else if (sk == SurfaceKind::Plane && pk != PathKind::Geodesic) continue;  // setting it is an error here
      else w.computed(key, "the previous segment's end heading");
    } else if (key == key::kStartPoint && !p.startPoint) {
      w.computed(key, defaults == PathDefaults::Own ? "the default start on this surface"
                                                    : "the previous segment's end point");
    } else {
      w.key(key, *printedValue(rowOf(pathKeys(), key), p));
    }
  }
}

// A surface's kind and the kind's own keys in its declaration order, each
// printed by its type.
void writeSurface(Writer& w, const SurfaceSpec& surface) {
  w.key("kind", quoted(toString(surface.kind)));
  for (const ParamDecl& decl : surfaceKeyDecls(surface.kind)) {
    const ParamValue& value = surface.params.at(decl.key);
    switch (decl.type) {
      case ParamType::Number: w.key(decl.key, number(std::get<double>(value))); break;
      case ParamType::Direction: w.key(decl.key, vec(std::get<std::array<double, 3>>(value))); break;
      case ParamType::Choice:
      case ParamType::Expression: w.key(decl.key, quoted(std::get<std::string>(value))); break;
    }
  }
}

void writeSegments(Writer& w, const SceneSpec& spec) {
  for (std::size_t i = 0; i < spec.segments.size(); ++i) {
    const SegmentSpec& seg = spec.segments[i];
    const std::string prefix = SceneSpec::segmentKey(i);
    w.header("[[segment]]", prefix);
    if (!seg.caption.empty()) w.key(std::string(key::kCaption), quoted(seg.caption));
    if (seg.title) w.key(std::string(key::kTitle), quoted(*seg.title));
    if (!seg.path) {
      w.key(std::string(key::kHold), number(seg.hold));
    } else if (seg.duration) {
      w.key(std::string(key::kDuration), number(*seg.duration));
    } else if (seg.speed) {
      w.key(std::string(key::kSpeed), number(*seg.speed));
    } else {
      w.computed(std::string(key::kDuration), "its length at the storyboard's speed (see [animation])");
    }
    // A scene of several surfaces names each segment's (scenes of one print as before).
    if (spec.surfaceCount() > 1) {
      if (seg.surface && i > 0) {
        w.key(std::string(key::kTransition), *printedValue(rowOf(segmentKeys(), key::kTransition), seg));
        if (seg.transition == SegmentSpec::Transition::Fade)
          w.key(std::string(key::kFadeSeconds), number(seg.fadeSeconds));
      }
      if (!seg.surface)
        w.computed(std::string(key::kSurface), fmt::format("surface {} (a {}), as {}", spec.surfaceIndexOf(i),
                                                           toString(spec.surfaceOf(i).kind), spec.surfaceKeyOf(i)));
    }
    if (seg.surface) {
      w.header("[segment.surface]", prefix + ".surface");
      writeSurface(w, *seg.surface);
    }
    if (seg.path) {
      const bool ownStart = i == 0 || seg.surface.has_value();
      w.header("[segment.path]", prefix + ".path");
      writePath(w, *seg.path, spec.surfaceOf(i).kind, false, ownStart ? PathDefaults::Own : PathDefaults::FromPrevious);
    }
    const CameraSpec& c = seg.camera;
    if (c.azimuthDeg || c.elevationDeg || c.distance || c.target || c.follow || c.fovDeg) {
      w.header("[segment.camera]", prefix + ".camera");
      writeKeys(w, segmentCameraKeys(), c);
    }
  }
}

}  // namespace

std::string writeScene(const SceneSpec& spec, const std::map<std::string, std::string>& notes) {
  Writer w(notes);
  const SurfaceKind sk = spec.surface.kind;

  w.section("ball");
  writeKeys(w, ballKeys(), spec.ball);

  w.section("surface");
  writeSurface(w, spec.surface);

  if (spec.plate) {
    w.section("plate");
    writeKeys(w, plateKeys(), *spec.plate);
  }

  if (!spec.isStoryboard()) {
    w.section("path");
    writePath(w, spec.path, sk, spec.plate.has_value(), PathDefaults::Own);
  }

  w.section("solver");
  writeKeys(w, solverKeys(), spec.solver);
  w.section("timeline");
  writeKeys(w, timelineKeys(), spec.timeline);
  w.section("render");
  writeKeys(w, renderKeys(), spec.render);
  w.section("figure");
  writeKeys(w, figureKeys(), spec.figure);

  w.section(std::string(key::kLabels));
  if (spec.labels.facts) {
    std::string list;
    for (const Fact f : *spec.labels.facts) list += (list.empty() ? "" : ", ") + quoted(toString(f));
    w.key(std::string(key::kFacts), spec.labels.facts->empty() ? quoted("none") : "[" + list + "]");
  } else {
    std::string chosen;
    for (const Fact f : resolveFacts(spec)) chosen += (chosen.empty() ? "" : ", ") + toString(f);
    w.key(std::string(key::kFacts), quoted("auto") + "  # for this scene: " + (chosen.empty() ? "none" : chosen));
  }

  w.section("animation");
  writeKeys(w, animationKeys(), spec.animation);
  writeSegments(w, spec);
  return w.text();
}

}  // namespace rollspin::scene
