#include "jobs/viewer_job.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/stage_log.hpp"
#include "export/gltf_export.hpp"
#include "jobs/render_jobs.hpp"
#include "jobs/scene_print.hpp"
#include "jobs/viewer_timeline.hpp"

namespace rollspin::jobs {

namespace {

// Text inside an HTML element whose content is raw (a <script>): only
// "</script" could end it early; "<\/" reads the same to the viewer's parser.
std::string rawScriptText(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    out += text[i];
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out += '\\';
  }
  return out;
}

// Text inside an HTML attribute or element: the five characters HTML reserves.
std::string htmlEscaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

// The template with each `{{key}}` replaced by its value, in one pass, so a
// value (the scene's text) is never searched for markers. A marker without a
// value, or a value without a marker, is a build fault.
std::string filled(std::string_view page, const std::vector<std::pair<std::string_view, std::string>>& values) {
  std::string out;
  std::size_t used = 0, from = 0;
  for (std::size_t at = page.find("{{"); at != std::string_view::npos; at = page.find("{{", from)) {
    const std::size_t end = page.find("}}", at);
    const std::string_view key = page.substr(at + 2, end == std::string_view::npos ? 0 : end - at - 2);
    const auto it = std::find_if(values.begin(), values.end(), [&](const auto& v) { return v.first == key; });
    if (it == values.end()) throw runtimeError(SourceLoc{"web/src/page.html"}, "unknown marker {{{{{}}}}}", key);
    out.append(page.substr(from, at - from)).append(it->second);
    from = end + 2;
    ++used;
  }
  if (used != values.size()) throw runtimeError(SourceLoc{"web/src/page.html"}, "a marker is missing");
  return out.append(page.substr(from));
}

}  // namespace

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t chunk = 0;
    for (std::size_t k = 0; k < 3; ++k) chunk = (chunk << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kAlphabet[(chunk >> (18 - 6 * k)) & 63u] : '=';
  }
  return out;
}

std::string viewerHtml(const DrawJob& job, const std::string& sourceName) {
  const scene::SceneSpec& spec = job.spec;
  const std::string_view bundle = embeddedViewerAsset("viewer.js");
  if (embeddedViewerAsset("page.html").empty() || bundle.empty())
    throw runtimeError(SourceLoc{"html"}, "this rollspin was built without its web viewer (web/node_modules missing)");
  // The meshes are the glTF exporter's (one mesher for every output), the
  // motion the solver's at the viewer's knots.
  StageLog::instance().record("viewer-glb");
  const std::string version = fmt::format("rollspin {}", ROLLSPIN_VERSION);
  const std::string sceneText = resolvedSceneText(sourceName, spec);
  // The meshes only: the page poses the nodes from its own timeline, and the
  // animation's keys (dense, for slerp to 1e-6 rad) would be most of its bytes.
  const std::vector<std::uint8_t> glb =
      gltf::exportGlb({&spec, &job.model, loadBallTexture(spec), version, sceneText, false, false});
  StageLog::instance().record("viewer-timeline");
  // The step count `rollspin timeline` uses: the scene's solve refines an automatic one.
  motion::SolverChoice choice = motion::chooseSolver(spec, job.model);
  static_cast<void>(motion::solveScene(spec, job.model, choice));
  const std::string timeline = viewerTimelineJson(sampleViewerTimeline(spec, job.model, choice));
  StageLog::instance().record("viewer-page");
  const std::string title = spec.render.title.empty() ? spec.name : spec.render.title;
  const std::string page = filled(embeddedViewerAsset("page.html"),
                                  {{"title", htmlEscaped(title + " · rollspin")},
                                   {"generator", htmlEscaped(version)},
                                   {"heading", htmlEscaped(title)},
                                   {"scene", rawScriptText(sceneText)},
                                   {"timeline", timeline},  // viewerTimelineJson writes '<' as \u003c
                                   {"glb", base64({reinterpret_cast<const char*>(glb.data()), glb.size()})},
                                   {"bundle", rawScriptText(bundle)}});
  return page;
}

void writeViewerHtml(const DrawJob& job, const std::string& sourceName, const std::filesystem::path& out) {
  const std::string page = viewerHtml(job, sourceName);
  AtomicFile file(out);
  file.write(page);
  file.commit();
}

}  // namespace rollspin::jobs
