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
constexpr int kMaxDelta = 96;          // one MSAA coverage sample on a high-contrast edge, plus text hinting
constexpr double kMeanDelta = 0.6;     // levels per channel averaged over the image: a few edges, not content
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

fs::path renderScene(const std::string& name, const std::vector<std::string>& extra) {
  const fs::path dir = test::freshTempDir("golden_" + name);
  const fs::path out = dir / (name + ".png");
  std::vector<std::string> args{"render", (test::sourceDir() / "tests/render/scenes" / (name + ".toml")).string(),
                                "--still", "-o", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const test::CliResult r = test::runRollspin(args);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return out;
}

void checkGolden(const std::string& name, const std::vector<std::string>& extra = {}) {
  const fs::path actualPath = renderScene(name, extra);
  const fs::path golden = fs::path(ROLLSPIN_GOLDEN_DIR) / (name + ".png");
  if (regenerate()) {
    fs::copy_file(actualPath, golden, fs::copy_options::overwrite_existing);
    std::printf("regenerated %s\n", golden.c_str());
    return;
  }
  ASSERT_TRUE(fs::exists(golden)) << "no reference " << golden << " (run with ROLLSPIN_REGENERATE_GOLDEN=1)";
  const media::Image actual = media::loadImage(actualPath, {});
  const media::Image expected = media::loadImage(golden, {});
  ASSERT_EQ(actual.width, expected.width);
  ASSERT_EQ(actual.height, expected.height);
  const media::ImageDifference d = media::compareImages(actual.view(), expected.view());
  const double share = visiblyDifferingShare(actual, expected);
  const bool ok = d.maxOverall() <= kMaxDelta && d.meanOverall() <= kMeanDelta && share <= kMaxVisibleShare;
  if (!ok) {
    const fs::path failures = ROLLSPIN_GOLDEN_FAILURE_DIR;
    fs::create_directories(failures);
    const fs::path keep = failures / (name + ".actual.png");
    const fs::path diff = failures / (name + ".diff.png");
    fs::copy_file(actualPath, keep, fs::copy_options::overwrite_existing);
    media::writePng(diff, media::differenceHeatMap(actual.view(), expected.view()).view());
    ADD_FAILURE() << name << ": max delta " << d.maxOverall() << " (limit " << kMaxDelta << "), mean "
                  << d.meanOverall() << " (limit " << kMeanDelta << "), differing pixels " << d.differingPixels
                  << ", by more than " << kVisibleDelta << " levels: " << share * 100 << " % (limit "
                  << kMaxVisibleShare * 100 << " %)\n  actual: " << keep << "\n  diff:   " << diff
                  << "\n  expected: " << golden;
  }
  EXPECT_LT(fs::file_size(golden), 200u * 1024u) << "keep golden PNGs small";
}

TEST(Golden, LollipopSideBySide) { checkGolden("lollipop_side_by_side", {"--at", "fraction=0.3"}); }
TEST(Golden, SphereInsideWithInset) { checkGolden("sphere_inside", {"--at", "fraction=0.3"}); }
TEST(Golden, BrockettPlate) { checkGolden("brockett_plate", {"--at", "fraction=0.3"}); }
TEST(Golden, TwinOnly) { checkGolden("twin_only", {"--at", "fraction=0.3"}); }
TEST(Golden, StrobeFigure) { checkGolden("strobe"); }
TEST(Golden, TransparentStill) { checkGolden("transparent", {"--at", "fraction=0.3"}); }

// The same scene rendered twice in one run gives byte-identical PNGs.
TEST(Determinism, SameSceneTwiceIsByteIdentical) {
  const std::string first = test::readFile(renderScene("lollipop_side_by_side", {"--at", "s=4"}));
  const std::string second = test::readFile(renderScene("lollipop_side_by_side", {"--at", "s=4"}));
  ASSERT_FALSE(first.empty());
  EXPECT_TRUE(first == second) << "two renders of the same scene differ";
}

}  // namespace
}  // namespace rollspin
