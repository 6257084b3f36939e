// jobs/remembered_output.hpp: the job record's `key: value` lines and their
// errors at FILE[rollspin:job]:LINE, the metadata and tags a job's output
// carries, and readRememberedOutput on every kind of file rollspin writes
// (PNG, GIF, MP4, WebM, a timeline's JSON sidecar, glTF, GLB, the viewer's
// HTML): the scene and job come back, and a file without them is BadInput
// naming it.
#include "jobs/remembered_output.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "media/sink_factory.hpp"
#include "model/rolling_model.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_writer.hpp"
#include "support/test_files.hpp"

namespace rollspin::jobs {
namespace remembered_output_test {

namespace fs = std::filesystem;

const char* const kRememberedCircle = "[ball]\nradius = 2.5\n[path]\nkind = \"circle\"\nradius = 3\n";

scene::SceneSpec rememberedScene(const std::string& extra = "") {
  scene::SceneSpec spec = scene::loadSceneText(std::string(kRememberedCircle) + extra, "remembered.toml");
  spec.name = "remembered";
  return spec;
}

// The error `call` throws (a test failure, and an empty error, when none).
template <typename Call>
Error rememberedErrorOf(Call call) {
  try {
    call();
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error thrown";
  return Error(ErrorKind::Runtime, {}, "");
}

bool rememberedHas(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

void writeRememberedFile(const fs::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary);
  out << bytes;
}

media::OutputMetadata sampleMetadata() {
  const scene::SceneSpec spec = rememberedScene();
  JobRecord job;
  job.kind = JobRecord::Kind::Clip;
  job.sceneName = "torus";
  job.frames = "0:1";
  return outputMetadata(spec, model::buildSceneModel(spec), job);
}

// A 2-frame clip (or one still) of `format` carrying `m`, as a job writes it.
fs::path writeRememberedOutput(const fs::path& file, const char* format, media::OutputUse use,
                               const media::OutputMetadata* m) {
  media::SinkOptions o;
  o.path = file;
  o.width = 32;
  o.height = 32;
  o.fpsNum = 10;
  if (m != nullptr && use == media::OutputUse::Still) o.metadata = *m;
  if (m != nullptr && std::string(format) == "gif") o.metadata = *m;
  if (m != nullptr && std::string(format) != "gif" && use == media::OutputUse::Animation)
    o.containerMetadata = metadataTags(*m);
  const media::OutputFormat* row = media::findOutputFormat(format, use);
  EXPECT_NE(row, nullptr) << format;
  const auto sink = media::openSink(*row, o);
  media::Image frame(32, 32);
  const int frames = use == media::OutputUse::Still ? 1 : 2;
  // Every frame is the same: the GIF's palette frames are any of them.
  for (std::size_t k = 0; k < sink->previewFrames(frames).size(); ++k) sink->preview(frame.view());
  for (int k = 0; k < frames; ++k) sink->write(frame.view());
  return sink->finish();
}

// A binary glTF: the 12-byte header, then one JSON chunk (length, "JSON", text).
std::string glbWith(const std::string& json, std::uint32_t statedLength) {
  const auto le32 = [](std::uint32_t v) {
    std::string s(4, '\0');
    for (int k = 0; k < 4; ++k) s[k] = static_cast<char>((v >> (8 * k)) & 0xff);
    return s;
  };
  return "glTF" + le32(2) + le32(static_cast<std::uint32_t>(20 + json.size())) + le32(statedLength) + "JSON" + json;
}

// ---- the job record ----

TEST(RememberedJobRecord, IsTheHeadersKeyValueLinesInOrder) {
  JobRecord clip;
  clip.kind = JobRecord::Kind::Clip;
  clip.sceneName = "torus";
  clip.frames = "0:9";
  EXPECT_EQ(writeJobRecord(clip), "render: clip\nscene: torus\nframes: 0:9\nfigure_layout: false\n");

  JobRecord figure;
  figure.kind = JobRecord::Kind::Figure;
  figure.sceneName = "lollipop";
  figure.at = "fraction=0.5";
  figure.figureLayout = true;
  EXPECT_EQ(writeJobRecord(figure), "render: figure\nscene: lollipop\nat: fraction=0.5\nfigure_layout: true\n");
}

TEST(RememberedJobRecord, ReadsBackEveryKindAndEveryOptionalField) {
  for (const JobRecord::Kind kind : {JobRecord::Kind::Still, JobRecord::Kind::Figure, JobRecord::Kind::Clip})
    for (const bool optional : {false, true}) {
      JobRecord job;
      job.kind = kind;
      job.sceneName = "scene-" + std::to_string(static_cast<int>(kind));
      if (optional) {
        job.at = "time=1.5";
        job.frames = "3:7";
        job.figureLayout = true;
      }
      const JobRecord back = parseJobRecord(writeJobRecord(job), "x[rollspin:job]");
      SCOPED_TRACE(writeJobRecord(job));
      EXPECT_EQ(back.kind, job.kind);
      EXPECT_EQ(back.sceneName, job.sceneName);
      EXPECT_EQ(back.at, job.at);
      EXPECT_EQ(back.frames, job.frames);
      EXPECT_EQ(back.figureLayout, job.figureLayout);
    }
}

TEST(RememberedJobRecord, FigureLayoutIsOnOnlyWhenItSaysTrue) {
  EXPECT_TRUE(parseJobRecord("render: still\nfigure_layout: true\n", "w").figureLayout);
  EXPECT_FALSE(parseJobRecord("render: still\nfigure_layout: false\n", "w").figureLayout);
  EXPECT_FALSE(parseJobRecord("render: still\nfigure_layout: yes\n", "w").figureLayout);
  EXPECT_FALSE(parseJobRecord("render: still\n", "w").figureLayout);
}

TEST(RememberedJobRecord, AnUnreadableLineIsBadInputAtItsLine) {
  struct Case {
    const char* text;
    int line;  // 0: the record as a whole
    const char* says;
  };
  // Blank lines count: line numbers are the file's, for an editor.
  for (const Case c : {Case{"render: still\nscene torus\n", 2, "expected 'key: value', got 'scene torus'"},
                       Case{"render: still\n\nsize: 3\n", 3, "unknown key 'size'"},
                       Case{"render: movie\n", 1, "render: expected still, figure or clip, got 'movie'"},
                       Case{"render:still\n", 1, "expected 'key: value'"},
                       Case{"scene: torus\nframes: 0:9\n", 0, "no 'render:' line"}}) {
    SCOPED_TRACE(c.text);
    const Error e = rememberedErrorOf([&] { (void)parseJobRecord(c.text, "clip.mp4[rollspin:job]"); });
    EXPECT_EQ(e.exitCode(), 2);
    EXPECT_EQ(e.where().file, "clip.mp4[rollspin:job]");
    EXPECT_EQ(e.where().line, c.line);
    EXPECT_TRUE(rememberedHas(e.message(), c.says)) << e.message();
  }
}

// ---- what an output carries ----

TEST(RememberedMetadata, CarriesTheSceneThatLoadsBackTheRecordTheVersionAndAltText) {
  const scene::SceneSpec spec = rememberedScene();
  const model::RollingModel model = model::buildSceneModel(spec);
  JobRecord job;
  job.kind = JobRecord::Kind::Still;
  job.sceneName = "remembered";
  const media::OutputMetadata m = outputMetadata(spec, model, job);
  EXPECT_EQ(m.title, "remembered") << "no render.title: the scene's name";
  EXPECT_EQ(m.job, writeJobRecord(job));
  // Loading the remembered text gives the same scene: written again, the same text.
  const scene::SceneSpec back = scene::loadSceneText(m.scene, "back.toml");
  EXPECT_EQ(scene::writeScene(back), m.scene);
  EXPECT_DOUBLE_EQ(back.ball.radius, 2.5);
  EXPECT_TRUE(std::regex_match(m.software, std::regex(R"(rollspin \d+\.\d+.*)"))) << m.software;
  EXPECT_EQ(m.description, describeScene(spec, model));

  const scene::SceneSpec titled = rememberedScene("[render]\ntitle = \"Once round\"\n");
  EXPECT_EQ(outputMetadata(titled, model::buildSceneModel(titled), job).title, "Once round");
}

TEST(RememberedMetadata, DescriptionNamesTheBallThePathAndTheSpinWhereItIsShown) {
  scene::SceneSpec spec = rememberedScene();
  const model::RollingModel model = model::buildSceneModel(spec);
  const std::string motion = "A ball of radius 2.5 rolls along a " + model.path->describe();
  std::vector<std::string> seen;
  for (const scene::RenderLayout layout : {scene::RenderLayout::SideBySide, scene::RenderLayout::Inset,
                                           scene::RenderLayout::Ball, scene::RenderLayout::Twin}) {
    spec.render.layout = layout;
    const std::string d = describeScene(spec, model);
    SCOPED_TRACE(scene::toString(layout));
    EXPECT_EQ(d.rfind(motion, 0), 0u) << d;
    EXPECT_EQ(d.back(), '.') << "one sentence";
    // The ball-only layout shows no spin; every other shows the Bloch sphere.
    EXPECT_EQ(rememberedHas(d, "Bloch sphere"), layout != scene::RenderLayout::Ball) << d;
    EXPECT_EQ(std::count(seen.begin(), seen.end(), d), 0) << "each layout says where the spin is";
    seen.push_back(d);
  }
}

TEST(RememberedMetadata, VideoTagsCarryEachFieldUnderItsName) {
  const media::OutputMetadata m{"T", "S", "J", "D", "W"};
  const auto tags = metadataTags(m);
  const std::map<std::string, std::string> byKey(tags.begin(), tags.end());
  EXPECT_EQ(byKey.size(), tags.size()) << "no key twice";
  const std::map<std::string, std::string> expected{{"title", "T"},        {"description", "D"},
                                                    {"comment", "D"},      {"rollspin_scene", "S"},
                                                    {"rollspin_job", "J"}, {"rollspin_software", "W"}};
  EXPECT_EQ(byKey, expected);
}

// ---- reading a file back ----

TEST(RememberedOutput, AStillRemembersItsSceneItsJobAndTheJobsSceneName) {
  const fs::path dir = test::freshTempDir("remembered_png");
  const media::OutputMetadata m = sampleMetadata();
  const fs::path png = writeRememberedOutput(dir / "still.png", "png", media::OutputUse::Still, &m);
  const RememberedOutput r = readRememberedOutput(png);
  EXPECT_EQ(r.metadata.scene, m.scene);
  EXPECT_EQ(r.metadata.job, m.job);
  EXPECT_EQ(r.metadata.description, m.description);
  EXPECT_EQ(r.sourceName, png.string() + "[rollspin:scene]") << "errors point into the file";
  EXPECT_EQ(r.sceneName, "torus") << "the job's scene name, not the file's stem";
  ASSERT_TRUE(r.job.has_value());
  EXPECT_EQ(r.job->kind, JobRecord::Kind::Clip);
  EXPECT_EQ(r.job->frames, "0:1");
}

TEST(RememberedOutput, WithoutASceneNameInTheJobTheFilesStemNamesIt) {
  const fs::path dir = test::freshTempDir("remembered_stem");
  media::OutputMetadata m = sampleMetadata();
  m.job = "render: still\n";
  const fs::path png = writeRememberedOutput(dir / "my_still.png", "png", media::OutputUse::Still, &m);
  EXPECT_EQ(readRememberedOutput(png).sceneName, "my_still");
}

TEST(RememberedOutput, GifMp4AndWebmRememberTheirSceneAndJob) {
  const fs::path dir = test::freshTempDir("remembered_video");
  const media::OutputMetadata m = sampleMetadata();
  // WebM (Matroska) upper-cases its tag names; the reader must not care.
  for (const char* format : {"gif", "mp4", "webm"}) {
    SCOPED_TRACE(format);
    const fs::path file =
        writeRememberedOutput(dir / (std::string("clip.") + format), format, media::OutputUse::Animation, &m);
    const RememberedOutput r = readRememberedOutput(file);
    EXPECT_EQ(r.metadata.scene, m.scene);
    EXPECT_EQ(r.metadata.job, m.job);
    EXPECT_EQ(r.metadata.description, m.description);
    EXPECT_EQ(r.metadata.software, m.software);
    EXPECT_EQ(r.sceneName, "torus");
    ASSERT_TRUE(r.job.has_value());
    EXPECT_EQ(r.job->kind, JobRecord::Kind::Clip);
  }
}

TEST(RememberedOutput, AVideoWithoutRollspinTagsIsBadInputSayingWhichIsMissing) {
  const fs::path dir = test::freshTempDir("remembered_untagged");
  const fs::path bare = writeRememberedOutput(dir / "bare.mp4", "mp4", media::OutputUse::Animation, nullptr);
  const Error none = rememberedErrorOf([&] { (void)readRememberedOutput(bare); });
  EXPECT_EQ(none.exitCode(), 2);
  EXPECT_EQ(none.where().file, bare.string());
  EXPECT_TRUE(rememberedHas(none.message(), "carries no rollspin metadata: no 'rollspin_scene' tag")) << none.what();

  // The scene without its job: incomplete, and said so.
  media::SinkOptions o;
  o.path = dir / "no_job.mp4";
  o.width = o.height = 32;
  o.containerMetadata = {{"rollspin_scene", "[ball]\nradius = 1\n"}};
  const auto sink = media::openSink(*media::findOutputFormat("mp4", media::OutputUse::Animation), o);
  sink->write(media::Image(32, 32).view());
  const fs::path noJob = sink->finish();
  const Error incomplete = rememberedErrorOf([&] { (void)readRememberedOutput(noJob); });
  EXPECT_EQ(incomplete.exitCode(), 2);
  EXPECT_TRUE(rememberedHas(incomplete.message(), "the 'rollspin_job' tag is missing")) << incomplete.what();
}

TEST(RememberedOutput, ABrokenJobRecordPointsAtItsLineInTheFile) {
  const fs::path dir = test::freshTempDir("remembered_bad_job");
  media::OutputMetadata m = sampleMetadata();
  m.job = "render: still\nscene: x\nwhat\n";
  const fs::path png = writeRememberedOutput(dir / "still.png", "png", media::OutputUse::Still, &m);
  const Error e = rememberedErrorOf([&] { (void)readRememberedOutput(png); });
  EXPECT_EQ(e.exitCode(), 2);
  EXPECT_EQ(e.where().file, png.string() + "[rollspin:job]");
  EXPECT_EQ(e.where().line, 3);
}

TEST(RememberedOutput, ATimelineIsReadFromItsJsonSidecar) {
  const fs::path dir = test::freshTempDir("remembered_timeline");
  const std::string scene = "[ball]\nradius = 1\n";
  writeRememberedFile(dir / "roll.csv.json", R"({"scene": "[ball]\nradius = 1\n", "rollspin": "rollspin 9.9"})");
  writeRememberedFile(dir / "roll.NPZ.json", R"({"scene": "[ball]\nradius = 1\n"})");
  const RememberedOutput csv = readRememberedOutput(dir / "roll.csv");
  EXPECT_EQ(csv.metadata.scene, scene);
  EXPECT_EQ(csv.metadata.software, "rollspin 9.9");
  EXPECT_FALSE(csv.job.has_value()) << "a timeline has no job record";
  EXPECT_EQ(csv.sceneName, "roll");
  EXPECT_EQ(csv.sourceName, (dir / "roll.csv").string() + "[rollspin:scene]") << "the name given, not the sidecar's";
  EXPECT_EQ(readRememberedOutput(dir / "roll.NPZ").metadata.scene, scene) << "the extension in any case";
}

TEST(RememberedOutput, GltfAndGlbCarryTheSceneOnTheBallNode) {
  const fs::path dir = test::freshTempDir("remembered_gltf");
  const std::string json =
      R"({"nodes": [{"name": "surface"}, {"name": "ball", "extras": {"rollspin": {"scene": "[ball]\nradius = 2\n"}}}]})";
  writeRememberedFile(dir / "roll.gltf", json);
  writeRememberedFile(dir / "roll.glb", glbWith(json, static_cast<std::uint32_t>(json.size())));
  for (const char* name : {"roll.gltf", "roll.glb"}) {
    SCOPED_TRACE(name);
    const RememberedOutput r = readRememberedOutput(dir / name);
    EXPECT_EQ(r.metadata.scene, "[ball]\nradius = 2\n");
    EXPECT_FALSE(r.job.has_value());
    EXPECT_EQ(r.sceneName, "roll");
  }
}

TEST(RememberedOutput, TheViewerPageCarriesTheSceneInItsScript) {
  const fs::path dir = test::freshTempDir("remembered_html");
  writeRememberedFile(dir / "roll.html",
                      "<html><script type=\"application/toml\" id=\"rollspin-scene\">[ball]\nradius = 4\n"
                      "</script><script>other()</script></html>");
  EXPECT_EQ(readRememberedOutput(dir / "roll.html").metadata.scene, "[ball]\nradius = 4\n");
}

TEST(RememberedOutput, FilesWithoutMetadataAreBadInputNamingTheFileAndWhat) {
  const fs::path dir = test::freshTempDir("remembered_refused");
  const std::string goodJson = R"({"nodes": [{"name": "ball", "extras": {"rollspin": {"scene": "x"}}}]})";
  fs::create_directories(dir / "folder.png");
  struct Case {
    const char* name;
    std::string bytes;  // "" with `write` false: no file at all
    bool write;
    const char* says;
  };
  const std::vector<Case> cases{
      {"absent.png", "", false, "cannot read"},
      {"folder.png", "", false, "cannot read"},
      {"broken.json", "{\"scene\": ", true, "is not valid JSON"},
      {"other.json", R"({"name": "not a timeline"})", true, "carries no rollspin metadata: no \"scene\" string"},
      {"number.json", R"({"scene": 3})", true, "no \"scene\" string"},
      {"noball.gltf", R"({"nodes": [{"name": "surface"}]})", true, "no node named 'ball' with extras.rollspin.scene"},
      {"notext.gltf", R"({"nodes": [{"name": "ball", "extras": {"rollspin": {"scene": 1}}}]})", true,
       "no node named 'ball'"},
      // Nodes that are not objects: still this file's error, not the JSON library's.
      {"odd.gltf", R"({"nodes": [1, "ball"]})", true, "no node named 'ball'"},
      {"number.gltf", R"({"nodes": [{"name": 1}]})", true, "no node named 'ball'"},
      {"short.glb", "glTF", true, "is truncated"},
      {"cut.glb", glbWith(goodJson, static_cast<std::uint32_t>(goodJson.size() + 1)), true, "is truncated"},
      {"plain.html", "<html><body>hello</body></html>", true, "no <script id=\"rollspin-scene\">"},
      {"cut.html", "<script id=\"rollspin-scene\">[ball]\n", true, "is truncated"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    if (c.write) writeRememberedFile(dir / c.name, c.bytes);
    const Error e = rememberedErrorOf([&] { (void)readRememberedOutput(dir / c.name); });
    EXPECT_EQ(e.exitCode(), 2);
    EXPECT_TRUE(rememberedHas(e.what(), (dir / c.name).string())) << e.what();
    EXPECT_TRUE(rememberedHas(e.message(), c.says)) << e.message();
  }
}

}  // namespace remembered_output_test
}  // namespace rollspin::jobs
