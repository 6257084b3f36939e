// Golden images: each scene under tests/render/scenes is rendered through the
// CLI and compared with tests/golden/NAME.png. ROLLSPIN_REGENERATE_GOLDEN=1
// rewrites the references instead. A failure writes NAME.actual.png and
// NAME.diff.png (heat map) under <build>/golden-failures and names them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>
#include <vector>

#include "media/image_compare.hpp"
#include "media/image_io.hpp"
#include "support/cli_runner.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

// Thresholds. On one machine llvmpipe is bit-exact (see Determinism below),
// so these only absorb the drift between CPUs: LLVM picks different SIMD
// widths (AVX2 vs AVX-512 vs NEON), which moves rasterisation of
// anti-aliased edges and the shadow's PCF taps by a few levels, and can flip
// a coverage sample on an edge pixel (up to a full sample of 4, i.e. ~64
// levels at a high-contrast edge). So: a single pixel may move a lot, the
// image as a whole may not.
constexpr int kMaxDelta = 96;       // one MSAA coverage sample on a high-contrast edge, plus text hinting
constexpr double kMeanDelta = 0.6;  // levels per channel averaged over the image: a few edges, not content
// Rounding drift (a level or two, e.g. a different FMA path in the sRGB
// encode) may touch most pixels; a visible change may not. So: at most 1 %
// of the pixels may differ by more than 16 levels in some channel.
constexpr int kVisibleDelta = 16;
constexpr double kMaxVisibleShare = 0.01;

double visiblyDifferingShare(const media::Image& a, const media::Image& b) {
  std::int64_t count = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    int delta = 0;
    for (int c = 0; c < 4; ++c) delta = std::max(delta, std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])));
    count += delta > kVisibleDelta ? 1 : 0;
  }
  return double(count) / double(a.rgba.size() / 4);
}

bool regenerate() {
  const char* v = std::getenv("ROLLSPIN_REGENERATE_GOLDEN");
  return v != nullptr && std::string(v) == "1";
}

// backend: the GL backend forced on the child (ROLLSPIN_GL), "" = inherited.
fs::path renderScene(const std::string& name, const std::vector<std::string>& extra, const std::string& backend = "") {
  const fs::path dir = test::freshTempDir("golden_" + name + (backend.empty() ? "" : "_" + backend));
  const fs::path out = dir / (name + ".png");
  std::vector<std::string> args{"render",     (test::sourceDir() / "tests/render/scenes" / (name + ".toml")).string(),
                                "--still",    "-o",
                                out.string(), "--verbose"};
  args.insert(args.end(), extra.begin(), extra.end());
  std::vector<std::string> env;
  if (!backend.empty()) env.push_back("ROLLSPIN_GL=" + backend);
  const test::CliResult r = test::runRollspin(args, {}, 0, env);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  // The backend asked for is the one that drew (--verbose names it).
  if (!backend.empty()) {
    EXPECT_NE(r.err.find("gl: backend     " + backend), std::string::npos) << r.err;
  }
  return out;
}

// Whether `actualPath` matches `expectedPath` within the thresholds above;
// a failure keeps the actual image and a heat map under `label`.
void expectWithinThresholds(const fs::path& actualPath, const fs::path& expectedPath, const std::string& label) {
  const media::Image actual = media::loadImage(actualPath, {});
  const media::Image expected = media::loadImage(expectedPath, {});
  ASSERT_EQ(actual.width, expected.width);
  ASSERT_EQ(actual.height, expected.height);
  const media::ImageDifference d = media::compareImages(actual.view(), expected.view());
  const double share = visiblyDifferingShare(actual, expected);
  const bool ok = d.maxOverall() <= kMaxDelta && d.meanOverall() <= kMeanDelta && share <= kMaxVisibleShare;
  if (!ok) {
    const fs::path failures = test::buildDir() / "golden-failures";
    fs::create_directories(failures);
    const fs::path keep = failures / (label + ".actual.png");
    const fs::path diff = failures / (label + ".diff.png");
    fs::copy_file(actualPath, keep, fs::copy_options::overwrite_existing);
    media::writePng(diff, media::differenceHeatMap(actual.view(), expected.view()).view());
    ADD_FAILURE() << label << ": max delta " << d.maxOverall() << " (limit " << kMaxDelta << "), mean "
                  << d.meanOverall() << " (limit " << kMeanDelta << "), differing pixels " << d.differingPixels
                  << ", by more than " << kVisibleDelta << " levels: " << share * 100 << " % (limit "
                  << kMaxVisibleShare * 100 << " %)\n  actual: " << keep << "\n  diff:   " << diff
                  << "\n  expected: " << expectedPath;
  }
}

void checkGolden(const std::string& name, const std::vector<std::string>& extra, const std::string& backend) {
  const fs::path actualPath = renderScene(name, extra, backend);
  const fs::path golden = test::sourceDir() / "tests" / "golden" / (name + ".png");
  if (regenerate()) {
    // References come from one backend (the first in the list below).
    if (backend != "osmesa") GTEST_SKIP() << "references are regenerated with osmesa";
    fs::copy_file(actualPath, golden, fs::copy_options::overwrite_existing);
    std::printf("regenerated %s\n", golden.c_str());
    return;
  }
  ASSERT_TRUE(fs::exists(golden)) << "no reference " << golden << " (run with ROLLSPIN_REGENERATE_GOLDEN=1)";
  expectWithinThresholds(actualPath, golden, name + "." + backend);
  EXPECT_LT(fs::file_size(golden), 200u * 1024u) << "keep golden PNGs small";
}

struct GoldenScene {
  const char* name;
  std::vector<std::string> extra;
};
const std::vector<GoldenScene> kGoldenScenes{
    {"lollipop_side_by_side", {"--at", "fraction=0.3"}},
    {"sphere_inside", {"--at", "fraction=0.3"}},
    {"brockett_plate", {"--at", "fraction=0.3"}},
    {"twin_only", {"--at", "fraction=0.3"}},
    {"strobe", {}},
    {"transparent", {"--at", "fraction=0.3"}},
};

// Every golden through every GL backend (render/gl_backends.cpp), each held
// to the same thresholds: EGL here is the surfaceless platform on llvmpipe.
class Golden : public ::testing::TestWithParam<std::tuple<std::size_t, std::string>> {};

TEST_P(Golden, WithinThresholds) {
  const auto& [index, backend] = GetParam();
  checkGolden(kGoldenScenes[index].name, kGoldenScenes[index].extra, backend);
}

INSTANTIATE_TEST_SUITE_P(Backends, Golden,
                         ::testing::Combine(::testing::Range<std::size_t>(0, kGoldenScenes.size()),
                                            ::testing::Values(std::string("osmesa"), std::string("egl"))),
                         [](const auto& info) {
                           return std::string(kGoldenScenes[std::get<0>(info.param)].name) + "_" +
                                  std::get<1>(info.param);
                         });

// The two backends draw the same still: compared with each other (not only
// each with the reference), within the same thresholds.
TEST(GoldenBackends, EglStillMatchesOsMesa) {
  const std::vector<std::string> at{"--at", "fraction=0.3"};
  const fs::path osmesa = renderScene("lollipop_side_by_side", at, "osmesa");
  const fs::path egl = renderScene("lollipop_side_by_side", at, "egl");
  expectWithinThresholds(egl, osmesa, "lollipop_side_by_side.egl-vs-osmesa");
}

// The same scene rendered twice in one run gives byte-identical PNGs.
TEST(Determinism, SameSceneTwiceIsByteIdentical) {
  const std::string first = test::readFile(renderScene("lollipop_side_by_side", {"--at", "s=4"}));
  const std::string second = test::readFile(renderScene("lollipop_side_by_side", {"--at", "s=4"}));
  ASSERT_FALSE(first.empty());
  EXPECT_TRUE(first == second) << "two renders of the same scene differ";
}

}  // namespace
}  // namespace rollspin
