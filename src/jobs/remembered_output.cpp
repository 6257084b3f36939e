#include "jobs/remembered_output.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>

#include "core/text.hpp"
#include "media/container_tags.hpp"
#include "scene/scene_writer.hpp"

namespace rollspin::jobs {

namespace {

constexpr const char* kKindNames[] = {"still", "figure", "clip"};

// The video tags under which the metadata travels (Matroska upper-cases
// them; libavformat gives them back in any case, read in lower case).
constexpr const char* kSceneTag = "rollspin_scene";
constexpr const char* kJobTag = "rollspin_job";
constexpr const char* kDescriptionTag = "description";
constexpr const char* kSoftwareTag = "rollspin_software";

std::string fileBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(file, ec))
    throw badInput(SourceLoc{file.string()}, "cannot read '{}'", file.string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

std::string writeJobRecord(const JobRecord& job) {
  std::string out = fmt::format("render: {}\nscene: {}\n", kKindNames[static_cast<int>(job.kind)], job.sceneName);
  if (job.at) out += fmt::format("at: {}\n", *job.at);
  if (job.frames) out += fmt::format("frames: {}\n", *job.frames);
  out += fmt::format("figure_layout: {}\n", job.figureLayout);
  return out;
}

JobRecord parseJobRecord(const std::string& text, const std::string& where) {
  JobRecord job;
  std::istringstream lines(text);
  std::string line;
  bool kindSeen = false;
  for (int number = 1; std::getline(lines, line); ++number) {
    if (line.empty()) continue;
    const std::size_t colon = line.find(": ");
    const SourceLoc loc{where, number, 1};
    if (colon == std::string::npos) throw badInput(loc, "expected 'key: value', got '{}'", line);
    const std::string key = line.substr(0, colon), value = line.substr(colon + 2);
    if (key == "render") {
      const auto* found = std::find(std::begin(kKindNames), std::end(kKindNames), value);
      if (found == std::end(kKindNames)) throw badInput(loc, "render: expected still, figure or clip, got '{}'", value);
      job.kind = static_cast<JobRecord::Kind>(found - std::begin(kKindNames));
      kindSeen = true;
    } else if (key == "scene") job.sceneName = value;
    else if (key == "at") job.at = value;
    else if (key == "frames") job.frames = value;
    else if (key == "figure_layout") job.figureLayout = value == "true";
    else throw badInput(loc, "unknown key '{}' (expected render, scene, at, frames or figure_layout)", key);
  }
  if (!kindSeen) throw badInput(SourceLoc{where}, "the job record has no 'render:' line");
  return job;
}

std::string describeScene(const scene::SceneSpec& spec, const model::RollingModel& model) {
  // The path's own description names its surface ("circle of radius 3 (1 turns, ccw) on a plane …").
  const std::string motion =
      fmt::format("A ball of radius {:g} rolls along a {}", model.ballRadius, model.path->describe());
  switch (spec.render.layout) {
    case scene::RenderLayout::SideBySide: return motion + "; beside it the spin on the Bloch sphere.";
    case scene::RenderLayout::Inset: return motion + "; in an inset the spin on the Bloch sphere.";
    case scene::RenderLayout::Ball: return motion + ".";
    case scene::RenderLayout::Twin: return motion + ", shown as its twin, the spin on the Bloch sphere.";
  }
  return motion + ".";
}

media::OutputMetadata outputMetadata(const scene::SceneSpec& spec, const model::RollingModel& model,
                                     const JobRecord& job) {
  media::OutputMetadata m;
  m.title = spec.render.title.empty() ? spec.name : spec.render.title;
  m.scene = scene::writeScene(spec);
  m.job = writeJobRecord(job);
  m.description = describeScene(spec, model);
  m.software = "rollspin " ROLLSPIN_VERSION;
  return m;
}

std::vector<std::pair<std::string, std::string>> metadataTags(const media::OutputMetadata& m) {
  return {{"title", m.title}, {kDescriptionTag, m.description}, {"comment", m.description}, {kSceneTag, m.scene},
          {kJobTag, m.job},   {kSoftwareTag, m.software}};
}

namespace {

// A timeline's sidecar (NAME.csv.json, …): its scene; its job is a timeline's.
media::OutputMetadata fromJson(const std::string& bytes, const std::string& name) {
  const nlohmann::json doc = nlohmann::json::parse(bytes, nullptr, false);
  if (doc.is_discarded()) throw badInput(SourceLoc{name}, "'{}' is not valid JSON", name);
  // glTF (branch gltf): the node named "ball" carries extras.rollspin.scene.
  if (doc.contains("nodes") && doc["nodes"].is_array()) {
    for (const auto& node : doc["nodes"])
      if (node.is_object() && node.contains("name") && node["name"] == "ball" && node.contains("extras") &&
          node["extras"].contains("rollspin") && node["extras"]["rollspin"].contains("scene") &&
          node["extras"]["rollspin"]["scene"].is_string())
        return {"", node["extras"]["rollspin"]["scene"].get<std::string>(), "", "", ""};
    throw badInput(SourceLoc{name},
                   "'{}' carries no rollspin metadata: no node named 'ball' with "
                   "extras.rollspin.scene",
                   name);
  }
  if (!doc.is_object() || !doc.contains("scene") || !doc["scene"].is_string())
    throw badInput(SourceLoc{name}, "'{}' carries no rollspin metadata: no \"scene\" string", name);
  media::OutputMetadata m;
  m.scene = doc["scene"].get<std::string>();
  if (doc.contains("rollspin") && doc["rollspin"].is_string()) m.software = doc["rollspin"].get<std::string>();
  return m;
}

// glTF binary: a 12-byte header, then a JSON chunk (length, "JSON", text).
std::string glbJson(const std::string& bytes, const std::string& name) {
  const auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
    return v;
  };
  if (bytes.size() < 20 || bytes.compare(16, 4, "JSON") != 0 || 20 + std::size_t{u32(12)} > bytes.size())
    throw badInput(SourceLoc{name}, "'{}' is truncated: its glTF JSON chunk runs past the end", name);
  return bytes.substr(20, u32(12));
}

// The viewer's one-file HTML (branch viewer): the scene in
// <script type="application/toml" id="rollspin-scene">.
std::string htmlScene(const std::string& bytes, const std::string& name) {
  const std::size_t id = bytes.find("id=\"rollspin-scene\"");
  const std::size_t open = id == std::string::npos ? id : bytes.find('>', id);
  const std::size_t close = open == std::string::npos ? open : bytes.find("</script>", open);
  if (id == std::string::npos)
    throw badInput(SourceLoc{name}, "'{}' carries no rollspin metadata: no <script id=\"rollspin-scene\">", name);
  if (close == std::string::npos)
    throw badInput(SourceLoc{name}, "'{}' is truncated: its rollspin-scene script has no end tag", name);
  return bytes.substr(open + 1, close - open - 1);
}

media::OutputMetadata fromContainer(const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::map<std::string, std::string> tags = media::readContainerMetadata(file, SourceLoc{name});
  const auto tag = [&](const char* key) -> const std::string* {
    const auto it = tags.find(key);
    return it == tags.end() ? nullptr : &it->second;
  };
  if (!tag(kSceneTag))
    throw badInput(SourceLoc{name},
                   "'{}' carries no rollspin metadata: no '{}' tag (was it written by rollspin "
                   "render, without --no-metadata?)",
                   name, kSceneTag);
  if (!tag(kJobTag))
    throw badInput(SourceLoc{name}, "'{}': the '{}' tag is missing (its metadata is incomplete)", name, kJobTag);
  media::OutputMetadata m;
  m.scene = *tag(kSceneTag);
  m.job = *tag(kJobTag);
  if (const auto* d = tag(kDescriptionTag)) m.description = *d;
  if (const auto* s = tag(kSoftwareTag)) m.software = *s;
  if (const auto* t = tag("title")) m.title = *t;
  return m;
}

}  // namespace

RememberedOutput readRememberedOutput(const std::filesystem::path& given) {
  std::filesystem::path file = given;
  const std::string extension = asciiLowercase(file.extension().string());
  // A timeline: its sidecar holds the scene.
  if (extension == ".csv" || extension == ".npy" || extension == ".npz") file += ".json";
  const std::string name = file.string();
  const std::string bytes = fileBytes(file);
  RememberedOutput out;
  const std::string ext = asciiLowercase(file.extension().string());
  if (ext == ".json" || ext == ".gltf") out.metadata = fromJson(bytes, name);
  else if (ext == ".glb") out.metadata = fromJson(glbJson(bytes, name), name);
  else if (ext == ".html" || ext == ".htm") out.metadata.scene = htmlScene(bytes, name);
  else if (media::carrierOf(bytes) != media::MetadataCarrier::Other && ext != ".mp4" && ext != ".mov" && ext != ".webm")
    out.metadata = media::parseOutputMetadata(bytes, name);
  else out.metadata = fromContainer(file);
  out.sourceName = fmt::format("{}[{}]", given.string(), media::kSceneKey);
  out.sceneName = given.stem().string();
  if (!out.metadata.job.empty()) {
    out.job = parseJobRecord(out.metadata.job, fmt::format("{}[{}]", given.string(), media::kJobKey));
    if (!out.job->sceneName.empty()) out.sceneName = out.job->sceneName;
  }
  return out;
}

}  // namespace rollspin::jobs
