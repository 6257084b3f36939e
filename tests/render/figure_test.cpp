// Vector figures (PDF/SVG, issue 17): the figure rasterized by poppler and
// librsvg matches the PNG still; fonts are embedded and text is searchable;
// lines are vector paths, cut where the GL depth buffer hides them; the
// figure of the lollipop is small; the figure keys are validated.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>

#include "media/image_io.hpp"
#include "render/gl_context.hpp"
#include "render/mesh_builders.hpp"
#include "render/renderer.hpp"
#include "render/vector_figure.hpp"
#include "support/cli_runner.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

// A tool's stdout (poppler-utils, librsvg2-bin; scripts/install-deps.sh).
std::string run(const std::string& command, int* status = nullptr) {
  std::string out;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return out;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  const int rc = pclose(pipe);
  if (status != nullptr) *status = rc;
  return out;
}

void renderStill(const std::string& sceneName, const fs::path& out, std::vector<std::string> extra) {
  std::vector<std::string> args{"render", test::shippedScenePath(sceneName), "--still", "-o", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const test::CliResult r = test::runRollspin(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_TRUE(fs::exists(out));
}

// RGBA over white paper, as a PDF viewer shows a transparent figure.
media::Image overWhite(const media::Image& in) {
  media::Image out = in;
  for (std::size_t i = 0; i < out.rgba.size(); i += 4) {
    const int a = in.rgba[i + 3];
    for (int c = 0; c < 3; ++c)
      out.rgba[i + c] = static_cast<std::uint8_t>((in.rgba[i + c] * a + 255 * (255 - a) + 127) / 255);
    out.rgba[i + 3] = 255;
  }
  return out;
}

struct Difference {
  double mean = 0.0;      // levels per colour channel, over the image
  double farShare = 0.0;  // share of pixels with a channel off by more than kFar
};
constexpr int kFar = 64;
Difference colourDifference(const media::Image& a, const media::Image& b) {
  Difference d;
  std::int64_t sum = 0, far = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int delta = std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c]));
      sum += delta;
      worst = std::max(worst, delta);
    }
    far += worst > kFar ? 1 : 0;
  }
  const double pixels = double(a.rgba.size() / 4);
  d.mean = double(sum) / (3.0 * pixels);
  d.farShare = double(far) / pixels;
  return d;
}

// Tolerance of a rasterized figure against the PNG still of the same view.
// Measured at 640x360 (lollipop, sphere-inside; Debian 12's poppler 22.12
// and librsvg 2.54): mean 1.2–1.3 levels per channel and 0.17–0.29 % of the
// pixels off by more than 64 levels through librsvg; 1.8–2.1 levels and
// 0.70–0.71 % through poppler (its image resampling is coarser). What
// differs, and why it may: the meshes are rendered at 300 dpi over 120 mm
// (1417 px wide) and resampled to 640 by the rasterizer, where GL renders
// them at 640 with 4x MSAA; text is FreeType outlines, not stb_truetype's
// bitmaps; the arrows are flat vector shapes, not lit solids; line ends and
// joins are round. All of that lives on edges and strokes. The bounds leave
// ~20 % (mean) and ~1.7x (far pixels) of headroom over poppler; moving every
// label by a third of its height (a baseline bug) gives 2.4–3.1 levels and
// 1.4–1.7 %, which they catch, as they catch a missing or misplaced layer.
constexpr double kMaxMean = 2.5;
constexpr double kMaxFarShare = 0.012;

void expectMatches(const media::Image& still, const media::Image& figure, const std::string& what) {
  ASSERT_EQ(figure.width, still.width) << what;
  ASSERT_EQ(figure.height, still.height) << what;
  const Difference d = colourDifference(still, figure);
  std::printf("%s vs PNG still: mean %.3f levels, %.3f%% of pixels off by more than %d\n", what.c_str(), d.mean,
              100.0 * d.farShare, kFar);
  EXPECT_LE(d.mean, kMaxMean) << what;
  EXPECT_LE(d.farShare, kMaxFarShare) << what;
}

TEST(FigureCli, PdfAndSvgRasterizedMatchThePngStill) {
  const fs::path dir = test::freshTempDir("figure_match");
  const std::vector<std::string> size{"--width", "640", "--height", "360"};
  for (const std::string name : {"lollipop", "sphere-inside"}) {
    std::vector<std::string> opaque = size;
    // The views' backdrops, as in the PNG. 5 pt over 120 mm gives the text
    // about the share of the image it had before figures were laid out at
    // their printed size, so the bounds below keep their meaning (FreeType
    // and stb_truetype text differ on every glyph: at the default 8 pt the
    // mean is 4.7 levels from the text alone).
    opaque.insert(opaque.end(), {"--set", "figure.transparent=false", "--set", "figure.font_size_pt=5"});
    // A PNG still of a scene that sets a [figure] key is laid out as the
    // figure is (its text at the printed size): the same composition.
    renderStill(name, dir / (name + ".png"), opaque);
    renderStill(name, dir / (name + ".pdf"), opaque);
    renderStill(name, dir / (name + ".svg"), opaque);
    const std::string pdfPng = (dir / (name + "_pdf")).string();
    int status = 0;
    run("pdftoppm -png -scale-to-x 640 -scale-to-y 360 -singlefile " + (dir / (name + ".pdf")).string() + " " + pdfPng,
        &status);
    ASSERT_EQ(status, 0) << "pdftoppm (poppler-utils) failed";
    run("rsvg-convert -w 640 -h 360 -o " + (dir / (name + "_svg.png")).string() + " " +
            (dir / (name + ".svg")).string(),
        &status);
    ASSERT_EQ(status, 0) << "rsvg-convert (librsvg2-bin) failed";
    const media::Image still = media::loadImage(dir / (name + ".png"), {});
    expectMatches(still, overWhite(media::loadImage(pdfPng + ".png", {})), name + ".pdf (poppler)");
    expectMatches(still, overWhite(media::loadImage(dir / (name + "_svg.png"), {})), name + ".svg (librsvg)");
  }
}

// At a journal column and the default 8 pt, the PNG still of the same
// aspect shows the figure's composition scaled: outside the text boxes the
// figure's layout reports (render --layout-json), the rasterized PDF
// matches the PNG within the bounds above; inside each box the PNG has ink
// (its text is where the figure's is). The text itself is compared only by
// place: FreeType outlines against stb_truetype bitmaps differ on every
// glyph, 4.7 levels of mean at this size from the text alone.
TEST(FigureCli, ThePngStillKeepsTheFiguresCompositionAtAColumnAtEightPoints) {
  const fs::path dir = test::freshTempDir("figure_column");
  const std::vector<std::string> keys{"--width",  "640",
                                      "--height", "360",
                                      "--set",    "figure.transparent=false",
                                      "--set",    "figure.width=column",
                                      "--set",    "figure.font_size_pt=8"};
  for (const std::string name : {"lollipop", "sphere-inside"}) {
    renderStill(name, dir / (name + ".png"), keys);
    std::vector<std::string> figureArgs = keys;
    figureArgs.insert(figureArgs.end(), {"--layout-json", (dir / (name + ".json")).string()});
    renderStill(name, dir / (name + ".pdf"), figureArgs);
    const std::string pdfPng = (dir / (name + "_pdf")).string();
    int status = 0;
    run("pdftoppm -png -scale-to-x 640 -scale-to-y 360 -singlefile " + (dir / (name + ".pdf")).string() + " " + pdfPng,
        &status);
    ASSERT_EQ(status, 0) << "pdftoppm (poppler-utils) failed";
    const media::Image still = media::loadImage(dir / (name + ".png"), {});
    media::Image figure = overWhite(media::loadImage(pdfPng + ".png", {}));
    ASSERT_EQ(figure.width, still.width);
    // The text boxes, in page points, scaled to the 640-pixel images.
    const std::string json = test::readFile(dir / (name + ".json"));
    std::smatch m;
    ASSERT_TRUE(std::regex_search(json, m, std::regex(R"("width_pt": ([0-9.]+))")));
    const double scale = 640.0 / std::stod(m[1]);
    const std::regex boxPattern(
        R"re("text": "[^"]*", "box": \[([0-9.\-]+), ([0-9.\-]+), ([0-9.\-]+), ([0-9.\-]+)\])re");
    media::Image stillMasked = still;
    int boxes = 0, inked = 0;
    for (auto it = std::sregex_iterator(json.begin(), json.end(), boxPattern); it != std::sregex_iterator(); ++it) {
      ++boxes;
      // A pixel of slack round each box: the rasterizers' anti-aliasing.
      const int x0 = std::max(0, int(std::floor(std::stod((*it)[1]) * scale)) - 1);
      const int y0 = std::max(0, int(std::floor(std::stod((*it)[2]) * scale)) - 1);
      const int x1 = std::min(still.width - 1, int(std::ceil(std::stod((*it)[3]) * scale)) + 1);
      const int y1 = std::min(still.height - 1, int(std::ceil(std::stod((*it)[4]) * scale)) + 1);
      int darkest = 255;
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          std::uint8_t* a = &stillMasked.rgba[(std::size_t(y) * still.width + x) * 4];
          std::uint8_t* b = &figure.rgba[(std::size_t(y) * still.width + x) * 4];
          darkest = std::min({darkest, int(a[0]), int(a[1]), int(a[2])});
          for (int c = 0; c < 3; ++c) a[c] = b[c] = 255;
        }
      inked += darkest < 128 ? 1 : 0;
    }
    EXPECT_GE(boxes, 8) << name;
    EXPECT_EQ(inked, boxes) << name << ": a text box of the figure's layout holds no text in the PNG still";
    expectMatches(stillMasked, figure, name + " at 85 mm, 8 pt, outside the text");
  }
}

TEST(FigureCli, TransparentByDefaultWithoutARasterBackground) {
  const fs::path dir = test::freshTempDir("figure_transparent");
  // 5 pt: the text's share of the image as in PdfAndSvgRasterizedMatchThePngStill.
  const std::vector<std::string> size{"--width", "640", "--height", "360", "--set", "figure.font_size_pt=5"};
  renderStill("lollipop", dir / "still.png",
              {"--width", "640", "--height", "360", "--transparent", "--set", "figure.font_size_pt=5"});
  renderStill("lollipop", dir / "fig.svg", size);
  int status = 0;
  run("rsvg-convert -w 640 -h 360 -o " + (dir / "fig.png").string() + " " + (dir / "fig.svg").string(), &status);
  ASSERT_EQ(status, 0);
  const media::Image figure = media::loadImage(dir / "fig.png", {});
  // The twin view's empty corner (top right: its sphere fills the middle
  // right to the view's edge) is the page: nothing painted there.
  EXPECT_EQ(figure.pixel(630, 12)[3], 0);
  EXPECT_EQ(figure.pixel(330, 60)[3], 0);  // above the floor in the ball view, clear of the text plates
  expectMatches(overWhite(media::loadImage(dir / "still.png", {})), overWhite(figure), "transparent lollipop.svg");
}

TEST(FigureCli, PdfEmbedsItsFontsAndTheLabelsAreText) {
  const fs::path dir = test::freshTempDir("figure_text");
  renderStill("lollipop", dir / "fig.pdf", {});
  const std::string fonts = run("pdffonts " + (dir / "fig.pdf").string());
  EXPECT_NE(fonts.find("DejaVuSans"), std::string::npos) << fonts;
  // Every font line: "emb sub uni" are yes yes yes (embedded, subset, ToUnicode).
  int fontLines = 0;
  std::size_t pos = fonts.find("---");
  for (pos = fonts.find('\n', pos); pos != std::string::npos && pos + 1 < fonts.size();
       pos = fonts.find('\n', pos + 1)) {
    const std::string line = fonts.substr(pos + 1, fonts.find('\n', pos + 1) - pos - 1);
    if (line.empty()) continue;
    ++fontLines;
    EXPECT_NE(line.find("yes yes yes"), std::string::npos) << line;
  }
  EXPECT_GE(fontLines, 2);  // regular and bold
  const std::string text = run("pdftotext " + (dir / "fig.pdf").string() + " -");
  for (const char* label : {"rolling ball", "Bloch sphere", "|0⟩", "|1⟩", "spin", "s = 9.42 of 18.85", "δ = 2π"})
    EXPECT_NE(text.find(label), std::string::npos) << label << " not in:\n" << text;
  const std::string info = run("pdfinfo " + (dir / "fig.pdf").string());
  EXPECT_NE(info.find("340.157 x 191.339 pts"), std::string::npos) << info;  // 120 mm wide, 16:9
}

TEST(FigureCli, LatinModernFromFontsLmodernAtTheGivenSize) {
  const fs::path dir = test::freshTempDir("figure_lm");
  renderStill(
      "lollipop", dir / "fig.pdf",
      {"--set", "figure.font=Latin Modern Roman", "--set", "figure.font_size_pt=8", "--set", "figure.width_in=6"});
  const std::string fonts = run("pdffonts " + (dir / "fig.pdf").string());
  EXPECT_NE(fonts.find("LMRoman10-Regular"), std::string::npos) << fonts;
  const std::string info = run("pdfinfo " + (dir / "fig.pdf").string());
  EXPECT_NE(info.find("432 x 243 pts"), std::string::npos) << info;  // 6 in
  // Greek and ⟩ are not in Latin Modern: they come from DejaVu Sans, not as boxes.
  const std::string text = run("pdftotext " + (dir / "fig.pdf").string() + " -");
  EXPECT_NE(text.find("|0⟩"), std::string::npos) << text;
  EXPECT_NE(text.find("ψ"), std::string::npos) << text;
}

TEST(FigureCli, TrailsArePathsAndTheLollipopFigureIsSmall) {
  const fs::path dir = test::freshTempDir("figure_paths");
  renderStill("lollipop", dir / "fig.svg", {});
  renderStill("lollipop", dir / "fig.pdf", {});  // 120 mm at 300 dpi, the defaults
  const std::string svg = test::readFile(dir / "fig.svg");
  int stroked = 0, longest = 0;
  for (std::size_t at = svg.find("<path"); at != std::string::npos; at = svg.find("<path", at + 1)) {
    const std::string element = svg.substr(at, svg.find("/>", at) - at);
    if (element.find("fill:none") == std::string::npos) continue;  // glyphs and arrows are filled
    ++stroked;
    int segments = 0;
    for (std::size_t l = element.find(" L "); l != std::string::npos; l = element.find(" L ", l + 1)) ++segments;
    longest = std::max(longest, segments);
  }
  // Contact path (full, travelled), marker trail, 3 great circles, 3 axes,
  // spin and field trails: 11 stroked paths; a trail has >= 240 samples.
  EXPECT_GE(stroked, 11);
  EXPECT_GE(longest, 200);
  // Only the shaded meshes are images: the ball view's and the twin's
  // opaque layer, and the twin's glass.
  int images = 0;
  for (std::size_t at = svg.find("<image"); at != std::string::npos; at = svg.find("<image", at + 1)) ++images;
  EXPECT_LE(images, 4);
  const auto bytes = fs::file_size(dir / "fig.pdf");
  std::printf("lollipop.pdf, 120 mm at 300 dpi: %ju bytes\n", static_cast<std::uintmax_t>(bytes));
  EXPECT_LE(bytes, 1000000u);
}

TEST(FigureCli, AFigureJobOpensNoEncoderAndWritesNoPng) {
  const fs::path dir = test::freshTempDir("figure_stages");
  const test::CliResult r = test::runRollspin(
      {"render", test::shippedScenePath("lollipop"), "--still", "--verbose", "-o", (dir / "fig.pdf").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("stage: figure"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("stage: encoder"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("stage: png"), std::string::npos) << r.err;
}

TEST(FigureCli, BadFigureKeysExit2NamingTheKey) {
  const fs::path dir = test::freshTempDir("figure_bad");
  struct Case {
    std::vector<std::string> extra;
    std::string output, key;
  };
  const std::vector<Case> cases{
      {{"--set", "figure.width_mm=100", "--set", "figure.width_in=4"}, "f.pdf", "figure.width_in"},
      {{"--set", "figure.width_mm=5"}, "f.pdf", "figure.width_mm"},
      {{"--set", "figure.font=No Such Family"}, "f.pdf", "figure.font"},
      {{"--set", "figure.font_size_pt=0"}, "f.pdf", "figure.font_size_pt"},
      {{"--set", "render.dpi=10"}, "f.pdf", "render.dpi"},
      {{"--set", "render.dpi=2400"}, "f.svg", "render.dpi"},  // an 11339 px raster
      {{"--set", "render.format=pdf"}, "f.png", "render.format"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args{"render", test::shippedScenePath("lollipop"), "--still", "-o",
                                  (dir / c.output).string()};
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    const test::CliResult r = test::runRollspin(args);
    EXPECT_EQ(r.exitCode, 2) << c.key << ": " << r.err;
    EXPECT_NE(r.err.find(c.key), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / c.output)) << c.key;
  }
  // A full disk is a runtime failure (exit 1); render.format decides for a name without extension.
  const test::CliResult full = test::runRollspin(
      {"render", test::shippedScenePath("lollipop"), "--still", "-o", "/dev/full", "--set", "render.format=pdf"});
  EXPECT_EQ(full.exitCode, 1) << full.err;
  EXPECT_NE(full.err.find("No space left"), std::string::npos) << full.err;
  // An animation refuses a figure format.
  const test::CliResult video = test::runRollspin(
      {"render", test::shippedScenePath("lollipop"), "-o", (dir / "v.mp4").string(), "--set", "render.format=pdf"});
  EXPECT_EQ(video.exitCode, 2) << video.err;
  EXPECT_NE(video.err.find("--still"), std::string::npos) << video.err;
}

// The depth test on its own: a line behind an opaque sphere is cut in two
// where the GL depth buffer has the sphere in front; the same line in
// front of it stays whole; a mark behind it is left out; and the depth
// read back is the sphere's.
TEST(FigureDepth, LinesBehindAnOpaqueMeshAreCutWhereTheDepthBufferSays) {
  using namespace render;
  DrawList list;
  list.width = 200;
  list.height = 100;
  View v;
  v.width = 200;
  v.height = 100;
  v.light.shadow = false;
  v.camera.position = {0, 0, 5};
  v.camera.viewFromWorld = glm::lookAt(v.camera.position, glm::vec3(0), glm::vec3(0, 1, 0));
  v.camera.clipFromView = glm::perspective(glm::radians(40.0f), 2.0f, 0.1f, 20.0f);
  list.views = {v};
  MeshItem ball;
  ball.mesh = uvSphere(48, 24);
  list.meshes.push_back(ball);
  PolylineItem behind, before;
  behind.points = {{-3.0f, 0.0f, -1.5f}, {3.0f, 0.0f, -1.5f}};
  behind.color = {1, 0, 0, 1};
  before.points = {{-3.0f, 0.5f, 1.5f}, {3.0f, 0.5f, 1.5f}};
  before.color = {0, 0, 1, 1};
  list.polylines = {behind, before};
  // Two marks (vector discs): one in front of the sphere, one hidden behind it.
  for (const float z : {1.5f, -1.6f}) {
    MeshItem mark;
    mark.mesh = uvSphere(12, 6);
    mark.worldFromModel = glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, -0.3f, z}), glm::vec3(0.1f));
    mark.material.color = {0, 1, 0};
    mark.figureDisc = true;
    list.meshes.push_back(mark);
  }

  const auto context = createContext();  // ROLLSPIN_GL chooses the backend
  Renderer renderer(*context, ShaderLibrary{});
  FigureRasters rasters;
  rasters.width = 400;
  rasters.height = 200;
  renderer.renderWithDepth(meshLayerOf(list, MeshLayer::Opaque, 400, 200), rasters.opaque, rasters.opaqueDepth);
  ASSERT_EQ(rasters.opaqueDepth.size(), 400u * 200u);
  EXPECT_LT(rasters.opaqueDepth[100 * 400 + 200], 0.999f);  // the sphere at the centre
  EXPECT_EQ(rasters.opaqueDepth[5 * 400 + 5], 1.0f);        // nothing in the corner
  EXPECT_EQ(rasters.opaque.pixel(5, 5)[3], 0);              // and no background
  EXPECT_EQ(rasters.opaque.pixel(200, 100)[3], 255);

  const fs::path out = test::freshTempDir("figure_depth") / "depth.svg";
  FigureStyle style;
  writeFigure(out, FigureFormat::Svg, list, rasters, style);
  const std::string svg = test::readFile(out);
  auto subpathsOf = [&](const std::string& stroke) {
    const std::size_t at = svg.find(stroke);
    if (at == std::string::npos) return -1;
    const std::string element = svg.substr(at, svg.find("/>", at) - at);
    int moves = 0;
    for (std::size_t m = element.find("M "); m != std::string::npos; m = element.find("M ", m + 1)) ++moves;
    return moves;
  };
  EXPECT_EQ(subpathsOf("stroke:rgb(100%,0%,0%)"), 2) << svg;  // behind: left and right of the sphere
  EXPECT_EQ(subpathsOf("stroke:rgb(0%,0%,100%)"), 1) << svg;  // in front: whole
  int marks = 0;
  for (std::size_t at = svg.find("fill:rgb(0%,100%,0%)"); at != std::string::npos;
       at = svg.find("fill:rgb(0%,100%,0%)", at + 1))
    ++marks;
  EXPECT_EQ(marks, 1) << svg;  // the front mark only, and as a vector, not in the image
  EXPECT_EQ(hasMeshes(meshLayerOf(list, MeshLayer::Opaque, 400, 200), MeshLayer::Opaque), true);
  EXPECT_EQ(meshLayerOf(list, MeshLayer::Opaque, 400, 200).meshes.size(), 1u);  // the sphere alone
}

}  // namespace
}  // namespace rollspin
