// `rollspin render` and `rollspin compare` as a user meets them: outputs,
// exit codes and messages for bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <cstdlib>
#include <fstream>

#include "media/image_io.hpp"
#include "support/cli_runner.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

std::string scene(const std::string& name) {
  return (test::sourceDir() / "tests/render/scenes" / (name + ".toml")).string();
}

TEST(RenderCli, StillHonoursSizeAndTransparency) {
  const fs::path dir = test::freshTempDir("cli_still");
  const auto r = test::runRollspin({"render", scene("twin_only"), "--still", "--width", "64", "--height", "48",
                                    "--transparent", "-o", (dir / "a.png").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const media::Image img = media::loadImage(dir / "a.png", {});
  EXPECT_EQ(img.width, 64);
  EXPECT_EQ(img.height, 48);
  EXPECT_EQ(img.pixel(0, 0)[3], 0);
}

TEST(RenderCli, CustomTextureIsUsed) {
  const fs::path dir = test::freshTempDir("cli_texture");
  media::Image tex(8, 4);
  for (std::size_t i = 0; i < tex.rgba.size(); i += 4) tex.rgba[i] = tex.rgba[i + 3] = 255;  // pure red
  media::writePng(dir / "red.png", tex.view(), media::PngChannels::Rgba);
  const auto r = test::runRollspin({"render", scene("transparent"), "--still", "--set",
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
    std::vector<std::string> args{"render", scene("lollipop_side_by_side"), "--still", "--width", "96", "--height",
                                  "54", "-o", (dir / "a.png").string()};
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
  for (const auto& [backend, message] : {std::pair{"osmesa", "OSMesa could not create"},
                                         std::pair{"egl", "eglCreateContext (OpenGL 4.5 core)"}}) {
    const auto r = test::runRollspin({"render", scene("twin_only"), "--still", "-o", (dir / "a.png").string()}, {}, 0,
                                     {std::string("ROLLSPIN_GL=") + backend});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "a.png"));
  }
  ::unsetenv("MESA_GL_VERSION_OVERRIDE");
}

TEST(SolveCli, NeedsNoGlContext) {
  // solve never creates a context: it works even where GL 4.5 is unavailable.
  ::setenv("MESA_GL_VERSION_OVERRIDE", "3.3", 1);
  const auto r = test::runRollspin({"solve", scene("lollipop_side_by_side")});
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
    std::vector<std::string> args{"render", scene("lollipop_side_by_side"), "--still", "-o", out};
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

}  // namespace
}  // namespace rollspin
