// `rollspin render` and `rollspin compare` as a user meets them: outputs,
// exit codes and messages for bad input.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "media/image_io.hpp"
#include "support/cli_runner.hpp"
#include "support/gl_machine.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

TEST(RenderCli, StillHonoursSizeAndTransparency) {
  const fs::path dir = test::freshTempDir("cli_still");
  const auto r = test::runRollspin({"render", test::renderTestScenePath("twin_only"), "--still", "--width", "64",
                                    "--height", "48", "--transparent", "-o", (dir / "a.png").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const media::Image img = media::loadImage(dir / "a.png", {});
  EXPECT_EQ(img.width, 64);
  EXPECT_EQ(img.height, 48);
  EXPECT_EQ(img.pixel(0, 0)[3], 0);
  EXPECT_NE(r.err.find("wrote " + (dir / "a.png").string()), std::string::npos) << r.err;

  // --quiet: the still is written and nothing is said.
  const auto quiet = test::runRollspin({"render", test::renderTestScenePath("twin_only"), "--still", "--width", "64",
                                        "--height", "48", "--quiet", "-o", (dir / "b.png").string()});
  ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_TRUE(quiet.err.empty()) << "--quiet: " << quiet.err;
  EXPECT_TRUE(fs::exists(dir / "b.png"));
}

TEST(RenderCli, CustomTextureIsUsed) {
  const fs::path dir = test::freshTempDir("cli_texture");
  media::Image tex(8, 4);
  for (std::size_t i = 0; i < tex.rgba.size(); i += 4) tex.rgba[i] = tex.rgba[i + 3] = 255;  // pure red
  media::writePng(dir / "red.png", tex.view(), media::PngChannels::Rgba);
  const auto r = test::runRollspin({"render", test::renderTestScenePath("transparent"), "--still", "--set",
                                    "ball.texture=" + (dir / "red.png").string(), "-o", (dir / "a.png").string()});
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST(RenderCli, CameraAndLayoutOptionsRender) {
  const fs::path dir = test::freshTempDir("cli_options");
  const std::vector<std::vector<std::string>> variants{
      {"--set", "render.follow=true", "--set", "render.layout=inset"},
      {"--set", "render.msaa=1", "--set", "render.labels=false", "--set", "render.azimuth_deg=30"},
      {"--set", "render.distance=20", "--set", "render.target=[0, 0, 1]", "--set", "render.elevation_deg=-20"},
      {"--set", "ball.marker=[1, 0, 0]", "--set", "render.strobe=4", "--at", "s=0"},
  };
  for (const auto& extra : variants) {
    std::vector<std::string> args{"render",
                                  test::renderTestScenePath("lollipop_side_by_side"),
                                  "--still",
                                  "--width",
                                  "96",
                                  "--height",
                                  "54",
                                  "-o",
                                  (dir / "a.png").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = test::runRollspin(args);
    EXPECT_EQ(r.exitCode, 0) << extra[1] << ": " << r.err;
    EXPECT_TRUE(fs::exists(dir / "a.png"));
    fs::remove(dir / "a.png");
  }
}

// No OpenGL 4.5 context (simulated by capping Mesa's version): a clear
// message and exit code 1, and no file — from each backend.
TEST(RenderCli, ContextFailureExitsOne) {
  const fs::path dir = test::freshTempDir("cli_nocontext");
  ::setenv("MESA_GL_VERSION_OVERRIDE", "3.3", 1);
  for (const auto& [backend, message] :
       {std::pair{"osmesa", "OSMesa could not create"}, std::pair{"egl", "eglCreateContext (OpenGL 4.5 core)"}}) {
    // A GPU's EGL driver ignores Mesa's cap: nothing to provoke there.
    if (std::string_view(backend) == "egl" && test::eglDevicesHere().hardware) continue;
    const auto r =
        test::runRollspin({"render", test::renderTestScenePath("twin_only"), "--still", "-o", (dir / "a.png").string()},
                          {}, 0, {std::string("ROLLSPIN_GL=") + backend});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "a.png"));
  }
  ::unsetenv("MESA_GL_VERSION_OVERRIDE");
}

TEST(SolveCli, NeedsNoGlContext) {
  // solve never creates a context: it works even where GL 4.5 is unavailable.
  ::setenv("MESA_GL_VERSION_OVERRIDE", "3.3", 1);
  const auto r = test::runRollspin({"solve", test::renderTestScenePath("lollipop_side_by_side")});
  ::unsetenv("MESA_GL_VERSION_OVERRIDE");
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

struct BadCase {
  std::vector<std::string> args;
  std::string expect;  // substring of stderr
};

TEST(RenderCli, BadInputExitsTwoWithAClearMessage) {
  const fs::path dir = test::freshTempDir("cli_bad");
  std::ofstream(dir / "corrupt.png") << "not an image";
  const std::string out = (dir / "x.png").string();
  const std::vector<BadCase> cases{
      {{"--width", "0"}, "--width"},
      {{"--height", "9000"}, "[1, 8192]"},
      {{"--set", "render.width=0"}, "render.width"},
      {{"--set", "render.layout=sideways"}, "render.layout"},
      {{"--set", "render.strobe=1"}, "render.strobe"},
      {{"--set", "render.msaa=3"}, "render.msaa"},
      {{"--set", "render.colour=1"}, "unknown key"},
      {{"--set", "ball.texture=" + (dir / "missing.png").string()}, "ball.texture"},
      {{"--set", "ball.texture=" + (dir / "corrupt.png").string()}, "not a readable PNG or JPG"},
      {{"--at", "fraction=2"}, "fraction"},
      {{"--at", "s=-1"}, "arc length"},
      {{"--at", "t=1"}, "--at"},
  };
  for (const BadCase& c : cases) {
    std::vector<std::string> args{"render", test::renderTestScenePath("lollipop_side_by_side"), "--still", "-o", out};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto r = test::runRollspin(args);
    EXPECT_EQ(r.exitCode, 2) << c.args.back() << ": " << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args.back() << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << "nothing may be written on error";
  }
}

TEST(RenderCli, UnknownLayoutInAFileNamesTheLine) {
  const fs::path dir = test::freshTempDir("cli_layout");
  std::ofstream(dir / "s.toml") << "[ball]\nradius = 1\n\n[render]\nlayout = \"sideways\"\n";
  const auto r = test::runRollspin({"render", (dir / "s.toml").string(), "--still", "-o", (dir / "x.png").string()});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("s.toml:5:"), std::string::npos) << r.err;
}

TEST(CompareCli, ExitCodesFollowTheTolerance) {
  const fs::path dir = test::freshTempDir("cli_compare");
  media::Image a(4, 4), b(4, 4);
  for (auto& v : a.rgba) v = 100;
  b = a;
  b.pixel(1, 1)[0] = 110;
  media::writePng(dir / "a.png", a.view(), media::PngChannels::Rgba);
  media::writePng(dir / "b.png", b.view(), media::PngChannels::Rgba);
  const std::string pa = (dir / "a.png").string(), pb = (dir / "b.png").string();
  EXPECT_EQ(test::runRollspin({"compare", pa, pa}).exitCode, 0);
  const auto different = test::runRollspin({"compare", pa, pb, "--diff", (dir / "d.png").string()});
  EXPECT_EQ(different.exitCode, 1);
  EXPECT_NE(different.out.find("max delta"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "d.png"));
  EXPECT_EQ(test::runRollspin({"compare", pa, pb, "--max-delta", "10", "--mean-delta", "1"}).exitCode, 0);
  EXPECT_EQ(test::runRollspin({"compare", pa, (dir / "missing.png").string()}).exitCode, 2);
}

// What a CI needs: exit 1 only for "differ", tolerances on the number of
// differing pixels and on SSIM, JSON, and alternate references.
TEST(CompareCli, ToleratesPixelsSsimAlternatesAndSpeaksJson) {
  const fs::path dir = test::freshTempDir("cli_compare_ci");
  media::Image a(20, 10);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x) {
      for (int c = 0; c < 3; ++c) a.pixel(x, y)[c] = static_cast<std::uint8_t>(10 * x + 5 * y);
      a.pixel(x, y)[3] = 255;
    }
  media::Image b = a, far = a;
  for (int x = 0; x < 3; ++x) b.pixel(x, 2)[0] = static_cast<std::uint8_t>(a.pixel(x, 2)[0] + 2);  // 3 px, 2 levels
  for (auto& v : far.rgba) v = static_cast<std::uint8_t>(255 - v);
  media::Image small(10, 10);
  for (const auto& [name, img] : {std::pair{"a.png", &a}, {"b.png", &b}, {"far.png", &far}, {"small.png", &small}})
    media::writePng(dir / name, img->view(), media::PngChannels::Rgba);
  auto p = [&](const char* name) { return (dir / name).string(); };
  auto run = [&](std::vector<std::string> args) {
    args.insert(args.begin(), "compare");
    return test::runRollspin(args);
  };
  EXPECT_EQ(run({p("a.png"), p("b.png")}).exitCode, 1);
  EXPECT_EQ(run({p("a.png"), p("b.png"), "--max-pixels", "3"}).exitCode, 0);
  EXPECT_EQ(run({p("a.png"), p("b.png"), "--max-pixels", "2"}).exitCode, 1);
  EXPECT_EQ(run({p("a.png"), p("b.png"), "--max-pixels", "1.5%"}).exitCode, 0);  // 3 of 200
  EXPECT_EQ(run({p("a.png"), p("b.png"), "--max-pixels", "1%"}).exitCode, 1);
  EXPECT_EQ(run({p("a.png"), p("b.png"), "--max-delta", "2"}).exitCode, 0);
  EXPECT_EQ(run({p("a.png"), p("b.png"), "--max-delta", "255", "--min-ssim", "0.99"}).exitCode, 0);
  EXPECT_EQ(run({p("a.png"), p("far.png"), "--max-delta", "255", "--min-ssim", "0.99"}).exitCode, 1);
  for (const char* bad : {"-3", "abc", "101%", "2.5"})
    EXPECT_EQ(run({p("a.png"), p("b.png"), "--max-pixels", bad}).exitCode, 2) << bad;
  EXPECT_EQ(run({p("a.png"), p("b.png"), "--min-ssim", "2"}).exitCode, 2);

  // Alternate references: passes when any one matches; the diff is against that one.
  const auto alt = run({p("a.png"), p("far.png"), p("small.png"), p("a.png"), "--diff", p("d.png")});
  EXPECT_EQ(alt.exitCode, 0) << alt.out << alt.err;
  EXPECT_NE(alt.out.find("matches " + p("a.png")), std::string::npos) << alt.out;
  const media::Image d = media::loadImage(dir / "d.png", {});
  EXPECT_EQ(d.width, 20) << "the diff of the match, not of the 10x10 reference";
  EXPECT_EQ(run({p("a.png"), p("far.png"), p("b.png")}).exitCode, 1);

  // Size mismatch: said on stderr with the prefix, a diff still written.
  const auto sized = run({p("a.png"), p("small.png"), "--diff", p("sized.png")});
  EXPECT_EQ(sized.exitCode, 1);
  EXPECT_NE(sized.err.find("rollspin: size mismatch: " + p("a.png") + " is 20x10, " + p("small.png") + " is 10x10"),
            std::string::npos)
      << sized.err;
  EXPECT_EQ(media::loadImage(dir / "sized.png", {}).width, 20);

  // An unwritable --diff is 2, never the "differ" code; nothing is compared.
  const auto unwritable = run({p("a.png"), p("b.png"), "--diff", (dir / "no" / "d.png").string()});
  EXPECT_EQ(unwritable.exitCode, 2) << unwritable.err;
  EXPECT_EQ(unwritable.out, "");

  const auto json = run({p("a.png"), p("b.png"), p("a.png"), "--json", "--max-pixels", "1"});
  EXPECT_EQ(json.exitCode, 0);
  for (const std::string& field : {std::string("\"pass\": true"), "\"matched\": \"" + p("a.png") + "\"",
                                   std::string("\"pixels_over_max_delta\": 3"), std::string("\"max_pixels\": \"1\""),
                                   std::string("\"ssim\": 1.000000000"), std::string("\"max_delta\": [2, 0, 0, 0]")})
    EXPECT_NE(json.out.find(field), std::string::npos) << field << " in\n" << json.out;
}

}  // namespace
}  // namespace rollspin
