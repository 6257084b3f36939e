// Choosing a GL backend as a user meets it: render.backend / ROLLSPIN_GL and
// their precedence, how auto falls back when a library is missing or broken,
// and the message and exit code of each failure (docs/gl-backends.md).
// Missing libraries are simulated with the loaders' documented overrides
// (ROLLSPIN_OSMESA_LIBRARY, ROLLSPIN_EGL_LIBRARY) and Mesa's and glvnd's own
// variables.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"
#include "support/gl_machine.hpp"

namespace rollspin {
namespace test {
// The shim's path (generated into egl_shim_path.cpp by tests/cli/CMakeLists.txt).
std::filesystem::path eglDeviceBaseShimPath();
}  // namespace test
namespace {

namespace fs = std::filesystem;

const std::string kMissingOsMesa = "ROLLSPIN_OSMESA_LIBRARY=/nonexistent/libOSMesa.so.8";
const std::string kMissingEgl = "ROLLSPIN_EGL_LIBRARY=/nonexistent/libEGL.so.1";

// A small still with --verbose; env replaces inherited variables.
test::CliResult renderSmall(const fs::path& out, std::vector<std::string> env, std::vector<std::string> extra = {}) {
  const std::string scene = test::renderTestScenePath("twin_only");
  std::vector<std::string> args{"render",   scene, "--still", "--width",    "64",
                                "--height", "48",  "-o",      out.string(), "--verbose"};
  args.insert(args.end(), extra.begin(), extra.end());
  return test::runRollspin(args, {}, 0, env);
}

using rollspin::test::has;

TEST(GlBackend, AutoRendersThroughEglWhenOsMesaIsMissing) {
  const fs::path dir = test::freshTempDir("gl_no_osmesa");
  const auto r = renderSmall(dir / "a.png", {"ROLLSPIN_GL=auto", kMissingOsMesa});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.err, "gl: backend     egl")) << r.err;
  EXPECT_TRUE(fs::exists(dir / "a.png"));
}

TEST(GlBackend, AutoRendersThroughEglWhenOsMesaIsBroken) {
  // Not a library at all: dlopen fails on it.
  const fs::path dir = test::freshTempDir("gl_broken_osmesa");
  std::ofstream(dir / "libOSMesa.so.8") << "not an ELF file";
  const auto r =
      renderSmall(dir / "a.png", {"ROLLSPIN_GL=auto", "ROLLSPIN_OSMESA_LIBRARY=" + (dir / "libOSMesa.so.8").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.err, "gl: backend     egl")) << r.err;
}

TEST(GlBackend, AutoUsesOsMesaWhenEglIsMissing) {
  const fs::path dir = test::freshTempDir("gl_no_egl");
  const auto r = renderSmall(dir / "a.png", {"ROLLSPIN_GL=auto", kMissingEgl});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.err, "gl: backend     osmesa")) << r.err;
}

// The lines `info` and --verbose print for the EGL context: the surfaceless
// platform where Mesa's CPU rasteriser is all there is, a device (never
// "none") where a GPU is.
std::vector<std::string> eglContextLines(const std::string& prefix) {
  if (test::eglDevicesHere().hardware)
    return {prefix + "backend     egl (device)", prefix + "GL_VENDOR", prefix + "GL_RENDERER",
            prefix + "GL_VERSION  4.5", prefix + "device      "};
  return {prefix + "backend     egl (surfaceless)", prefix + "GL_VENDOR", prefix + "GL_RENDERER",
          prefix + "GL_VERSION  4.5", prefix + "device      none (EGL surfaceless platform)"};
}

TEST(GlMachine, ReadsTheSurveyOfInfo) {
  const auto llvmpipe = test::parseEglDevices(
      "GL backends (ROLLSPIN_GL or render.backend chooses; \"auto\" by default):\n"
      "  osmesa: available, software — libOSMesa loads (software: llvmpipe)\n"
      "  egl: available, software — surfaceless platform (software); EGL devices 0: Mesa's software device "
      "(software)\n    EGL: a GPU through EGL_EXT_platform_device, else Mesa's surfaceless platform (llvmpipe)\n");
  EXPECT_FALSE(llvmpipe.hardware);
  EXPECT_EQ(llvmpipe.softwareIndex, 0);
  const auto gpu = test::parseEglDevices(
      "  osmesa: available, software — libOSMesa loads (software: llvmpipe)\n"
      "  egl: available, hardware — EGL devices 0: /dev/dri/renderD128 (hardware), 1: Mesa's software device "
      "(software)\n");
  EXPECT_TRUE(gpu.hardware);
  EXPECT_EQ(gpu.softwareIndex, 1);
  const auto none = test::parseEglDevices("  egl: unavailable — cannot load the EGL library\n");
  EXPECT_FALSE(none.hardware);
  EXPECT_FALSE(none.softwareIndex.has_value());
  // This machine's own survey reads as one or the other (the install script
  // brings Mesa's EGL, which always lists its software device): a change to
  // what `info` prints fails here rather than skipping tests quietly.
  const auto& here = test::eglDevicesHere();
  EXPECT_TRUE(here.hardware || here.softwareIndex.has_value());
}

TEST(GlBackend, VerbosePrintsTheContext) {
  const fs::path dir = test::freshTempDir("gl_verbose");
  const auto r = renderSmall(dir / "a.png", {"ROLLSPIN_GL=egl"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const std::string& line : eglContextLines("gl: ")) EXPECT_TRUE(has(r.err, line)) << line << "\n" << r.err;
  if (test::eglDevicesHere().hardware) {
    EXPECT_FALSE(has(r.err, "gl: device      none")) << r.err;
  }
}

TEST(GlBackend, SceneKeyWinsOverTheEnvironmentAndSetWinsOverTheFile) {
  const fs::path dir = test::freshTempDir("gl_precedence");
  std::ofstream(dir / "s.toml") << "extends = \"" << test::renderTestScenePath("twin_only")
                                << "\"\n[render]\nbackend = \"osmesa\"\n";
  const std::string file = (dir / "s.toml").string();
  auto backendOf = [&](const std::string& sceneFile, std::vector<std::string> extra) {
    std::vector<std::string> args{
        "render", sceneFile, "--still", "--width", "32", "--height", "24", "-o", (dir / "a.png").string(), "--verbose"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = test::runRollspin(args, {}, 0, {"ROLLSPIN_GL=egl"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return has(r.err, "gl: backend     egl") ? "egl" : has(r.err, "gl: backend     osmesa") ? "osmesa" : "?";
  };
  EXPECT_STREQ(backendOf(test::renderTestScenePath("twin_only"), {}), "egl");  // no key: the variable
  EXPECT_STREQ(backendOf(file, {}), "osmesa");                                 // the key wins over the variable
  EXPECT_STREQ(backendOf(file, {"--set", "render.backend=egl"}), "egl");       // --set wins over the file
}

TEST(GlBackend, UnknownNamesExitTwoNamingTheChoices) {
  const fs::path dir = test::freshTempDir("gl_unknown");
  const auto env = renderSmall(dir / "a.png", {"ROLLSPIN_GL=vulkan"});
  EXPECT_EQ(env.exitCode, 2) << env.err;
  EXPECT_TRUE(has(env.err, "ROLLSPIN_GL: unknown GL backend \"vulkan\"")) << env.err;
  EXPECT_TRUE(has(env.err, "\"auto\" | \"osmesa\" | \"egl\"")) << env.err;

  std::ofstream(dir / "s.toml") << "extends = \"" << test::renderTestScenePath("twin_only")
                                << "\"\n[render]\nbackend = \"vulkan\"\n";
  const auto key = test::runRollspin({"render", (dir / "s.toml").string(), "--still", "-o", (dir / "a.png").string()});
  EXPECT_EQ(key.exitCode, 2) << key.err;
  EXPECT_TRUE(has(key.err, "s.toml:3:11: render.backend")) << key.err;
  EXPECT_TRUE(has(key.err, "\"egl\"")) << key.err;
  EXPECT_FALSE(fs::exists(dir / "a.png"));
}

TEST(GlBackend, DeviceKeysAreCheckedWhereGiven) {
  const fs::path dir = test::freshTempDir("gl_device");
  const fs::path out = dir / "a.png";
  struct Case {
    std::vector<std::string> env, extra;
    int exitCode;
    std::string expect;
  };
  const std::vector<Case> cases{
      {{}, {"--set", "render.backend=osmesa", "--set", "render.device=0"}, 2, "render.device: applies to a backend"},
      {{}, {"--set", "render.device=-1"}, 2, "render.device: expected an EGL device index"},
      {{"ROLLSPIN_EGL_DEVICE=card0"}, {}, 2, "ROLLSPIN_EGL_DEVICE: expected an EGL device index"},
      // No such device: exit 1 with the list of the devices there are.
      {{"ROLLSPIN_GL=egl"}, {"--set", "render.device=37"}, 1, "no EGL device 37 here (EGL devices 0:"},
      {{"ROLLSPIN_GL=egl", "ROLLSPIN_EGL_DEVICE=/dev/dri/renderD199"}, {}, 1, "no EGL device /dev/dri/renderD199"},
  };
  for (const Case& c : cases) {
    const auto r = renderSmall(out, c.env, c.extra);
    EXPECT_EQ(r.exitCode, c.exitCode) << c.expect << ": " << r.err;
    EXPECT_TRUE(has(r.err, c.expect)) << c.expect << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.expect;
  }
}

TEST(GlBackend, ASoftwareDeviceAskedForSaysSo) {
  // Mesa lists its CPU rasteriser as an EGL device (index 0 where there is
  // no GPU, after the GPUs where there are): asking for it renders, and
  // --verbose says no GPU does the work.
  const auto index = test::eglDevicesHere().softwareIndex;
  if (!index) GTEST_SKIP() << "EGL lists no Mesa software device on this machine (rollspin info)";
  const fs::path dir = test::freshTempDir("gl_software_device");
  const auto r = renderSmall(dir / "a.png", {"ROLLSPIN_GL=auto", "ROLLSPIN_EGL_DEVICE=" + std::to_string(*index)});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.err, "gl: backend     egl (device)")) << r.err;
  EXPECT_TRUE(has(r.err, "no GPU is doing the work")) << r.err;
}

// Where NVIDIA's driver is the only EGL vendor, glvnd names the device
// extensions by their older combined name, EGL_EXT_device_base, alone (seen
// on an H200, driver 580.159.04). The devices must be listed all the same:
// they were not, and the GPU was reached only through the surfaceless
// platform, reported as software. The shim lists the client extensions so.
TEST(GlBackend, ListsEglDevicesWhereLibEglNamesOnlyDeviceBase) {
  const std::string shim = "ROLLSPIN_EGL_LIBRARY=" + test::eglDeviceBaseShimPath().string();
  const auto info = test::runRollspin({"info"}, {}, 0, {shim});
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_TRUE(has(info.out, "EGL devices 0: ")) << info.out;
  EXPECT_FALSE(has(info.out, "no EGL devices")) << info.out;
  const auto index = test::eglDevicesHere().softwareIndex;
  if (!index) GTEST_SKIP() << "EGL lists no Mesa software device on this machine (rollspin info)";
  const fs::path dir = test::freshTempDir("gl_device_base");
  const auto r = renderSmall(dir / "a.png", {"ROLLSPIN_GL=egl", "ROLLSPIN_EGL_DEVICE=" + std::to_string(*index), shim});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.err, "gl: backend     egl (device)")) << r.err;
}

TEST(GlBackend, EachFailureExitsOneWithTheReasonAndWhatToTry) {
  const fs::path dir = test::freshTempDir("gl_failures");
  const fs::path out = dir / "a.png";
  struct Case {
    std::vector<std::string> env;
    std::vector<std::string> expect;
    bool mesaOnly = false;  // provoked through Mesa's variables, which a GPU's driver ignores
  };
  const std::vector<Case> cases{
      // No EGL library.
      {{"ROLLSPIN_GL=egl", kMissingEgl}, {"cannot load the EGL library", "libegl1", "or try ROLLSPIN_GL=osmesa"}},
      // No OSMesa library.
      {{"ROLLSPIN_GL=osmesa", kMissingOsMesa}, {"cannot load the OSMesa library", "libosmesa6", "ROLLSPIN_GL=egl"}},
      // libEGL without a driver: glvnd read no vendor file.
      {{"ROLLSPIN_GL=egl", "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/vendor.json"},
       {"libEGL found no EGL driver", "10_nvidia.json"}},
      // eglInitialize failing (as in a container without the driver files).
      {{"ROLLSPIN_GL=egl", "LIBGL_DRIVERS_PATH=/nonexistent"},
       {"eglInitialize on the surfaceless platform failed: EGL_NOT_INITIALIZED", "ROLLSPIN_GL=osmesa"},
       true},
      // A driver without OpenGL 4.5 (Mesa capped at 3.3).
      {{"ROLLSPIN_GL=egl", "MESA_GL_VERSION_OVERRIDE=3.3"},
       {"eglCreateContext (OpenGL 4.5 core)", "EGL_BAD_MATCH"},
       true},
      // auto with nothing that works: every backend's reason.
      {{"ROLLSPIN_GL=auto", kMissingOsMesa, kMissingEgl},
       {"no GL backend could make an OpenGL 4.5 core context", "osmesa: cannot load", "egl: cannot load"}},
  };
  for (const Case& c : cases) {
    // With a GPU, ROLLSPIN_GL=egl takes its device, not Mesa's platform.
    if (c.mesaOnly && test::eglDevicesHere().hardware) continue;
    const auto r = renderSmall(out, c.env);
    EXPECT_EQ(r.exitCode, 1) << c.env.back() << ": " << r.err;
    for (const auto& part : c.expect) EXPECT_TRUE(has(r.err, part)) << part << "\n" << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.env.back();
  }
}

TEST(InfoCommand, PrintsTheBackendsAndTheContext) {
  const auto r = test::runRollspin({"info", "--backend", "egl"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const std::string& part : {std::string("osmesa: available"), std::string("egl: available")})
    EXPECT_TRUE(has(r.out, part)) << part << "\n" << r.out;
  for (const std::string& line : eglContextLines("")) EXPECT_TRUE(has(r.out, line)) << line << "\n" << r.out;
  // A backend that cannot be had: the survey first, then exit 1.
  const auto missing = test::runRollspin({"info", "--backend", "egl"}, {}, 0, {kMissingEgl});
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_TRUE(has(missing.out, "egl: unavailable — cannot load the EGL library")) << missing.out;
  const auto bad = test::runRollspin({"info", "--backend", "metal"});
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_TRUE(has(bad.err, "--backend: unknown GL backend \"metal\"")) << bad.err;
}

}  // namespace
}  // namespace rollspin
