// What a new user meets first: messages name what was typed (--width, not an
// invented --set), the key and bound that made a limit overflow, the option
// parser speaks as rollspin and suggests the option meant, a preset does not
// silently override an explicit --set, and --version exists.
#include <gtest/gtest.h>

#include "support/cli_runner.hpp"

namespace test = rollspin::test;

namespace {

TEST(Messages, SizeFlagsAreNamedAsTyped) {
  const auto dir = test::freshTempDir("messages_size");
  const auto odd = test::runRollspin(
      {"render", test::shippedScenePath("lollipop"), "--width", "641", "-o", (dir / "v.mp4").string()});
  EXPECT_EQ(odd.exitCode, 2);
  EXPECT_NE(odd.err.find("rollspin: error: --width 641: "), std::string::npos) << odd.err;
  EXPECT_EQ(odd.err.find("--set"), std::string::npos) << odd.err;
#if defined(ROLLSPIN_ADDRESS_SANITIZER)
  return;  // AddressSanitizer reserves terabytes of address space: RLIMIT_AS cannot be set
#endif
  // The frame-memory check, in a process limited to 1.5 GiB.
  const auto big = test::runRollspin({"render", test::shippedScenePath("lollipop"), "--still", "--width", "8192",
                                      "--height", "8192", "-o", (dir / "s.png").string()},
                                     {}, 1536ULL << 20);
  EXPECT_EQ(big.exitCode, 2) << big.err;
  EXPECT_NE(big.err.find("rollspin: error: --height 8192: 8192x8192"), std::string::npos) << big.err;
}

TEST(Messages, ATinyBallIsNamedWithItsBound) {
  const auto r = test::runRollspin({"solve", test::shippedScenePath("lollipop"), "--set", "ball.radius=1e-300"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--set ball.radius=1e-300: ball.radius = 1e-300"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ball.radius must be at least"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("path.radius"), std::string::npos) << r.err;
}

TEST(Messages, ExactlyIntegralNumbersAreIntegers) {
  const auto steps = test::runRollspin({"solve", test::shippedScenePath("lollipop"), "--set", "solver.steps=1e5"});
  EXPECT_EQ(steps.exitCode, 0) << steps.err;
  EXPECT_NE(steps.out.find("(100000 steps)"), std::string::npos) << steps.out;
  const auto dir = test::freshTempDir("messages_samples");
  const auto samples = test::runRollspin({"timeline", test::shippedScenePath("lollipop"), "--set",
                                          "timeline.samples=1e3", "-o", (dir / "t.csv").string()});
  EXPECT_EQ(samples.exitCode, 0) << samples.err;
  EXPECT_NE(samples.err.find("wrote 1000 samples"), std::string::npos) << samples.err;
  const auto fraction = test::runRollspin({"solve", test::shippedScenePath("lollipop"), "--set", "solver.steps=1e5.5"});
  EXPECT_EQ(fraction.exitCode, 2);
  const auto half = test::runRollspin({"solve", test::shippedScenePath("lollipop"), "--set", "solver.steps=100.5"});
  EXPECT_EQ(half.exitCode, 2);
  EXPECT_NE(half.err.find("solver.steps"), std::string::npos) << half.err;
}

TEST(Messages, ParserErrorsSpeakAsRollspinAndSuggest) {
  const auto typo = test::runRollspin({"solve", test::shippedScenePath("lollipop"), "--sett", "ball.radius=2"});
  EXPECT_EQ(typo.exitCode, 2);
  EXPECT_EQ(typo.err.rfind("rollspin: error: ", 0), 0u) << typo.err;
  EXPECT_NE(typo.err.find("did you mean --set?"), std::string::npos) << typo.err;
  const auto still = test::runRollspin({"render", test::shippedScenePath("lollipop"), "--stil"});
  EXPECT_NE(still.err.find("did you mean --still?"), std::string::npos) << still.err;
  const auto range = test::runRollspin({"compare", "a.png", "b.png", "--max-delta", "abc"});
  EXPECT_EQ(range.exitCode, 2);
  EXPECT_EQ(range.err.rfind("rollspin: error: --max-delta", 0), 0u) << range.err;
  EXPECT_EQ(range.err.find("0.000000"), std::string::npos) << range.err;
  const auto command = test::runRollspin({"rendr", test::shippedScenePath("lollipop")});
  EXPECT_NE(command.err.find("did you mean 'render'?"), std::string::npos) << command.err;
  const auto far = test::runRollspin({"solve", test::shippedScenePath("lollipop"), "--zzzzzz"});
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << "no wild guesses: " << far.err;
}

TEST(Messages, AnExplicitSetWinsOverAQualityPresetAndSaysSo) {
  const auto dir = test::freshTempDir("messages_quality");
  const auto r = test::runRollspin({"render", test::shippedScenePath("lollipop"), "--quality", "low", "--set",
                                    "animation.fps=29.97", "--frames", "0:0", "-o", (dir / "q.mp4").string()});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("--quality low would set animation.fps=15; keeping --set animation.fps=29.97"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("854x480 @ 30000/1001"), std::string::npos) << "the preset's size, the explicit rate: " << r.err;
}

TEST(Messages, VersionNamesTheReleaseAndWithVerboseTheBackend) {
  const auto r = test::runRollspin({"--version"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.rfind("rollspin 0.", 0), 0u) << r.out;
  EXPECT_TRUE(r.out.find("(git ") != std::string::npos || r.out.find("not built from a git clone") != std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("GL backend"), std::string::npos);
  const auto v = test::runRollspin({"--version", "--verbose"});
  EXPECT_EQ(v.exitCode, 0);
  // The backend a render would get (ROLLSPIN_GL chooses in CI's second pass) and its GL version.
  EXPECT_TRUE(v.out.find("GL backend: osmesa") != std::string::npos ||
              v.out.find("GL backend: egl") != std::string::npos)
      << v.out;
  EXPECT_NE(v.out.find("4.5 (Core Profile)"), std::string::npos) << v.out;
}

}  // namespace

namespace {

// solve reports the same sheet for every method at an exact half turn.
TEST(Messages, SpinorAngleAtAHalfTurnIsTheSameForEveryMethod) {
  const std::string scene = (test::sourceDir() / "scenes" / "sphere-inside.toml").string();
  for (const char* method : {"exact", "magnus4", "frame4", "magnus6", "rk4"}) {
    const auto r = test::runRollspin(
        {"solve", scene, "--set", "ball.radius=0.75", "--set", std::string("solver.method=") + method, "--json"});
    ASSERT_EQ(r.exitCode, 0) << method << r.err;
    const auto at = r.out.find("\"spinor_angle\": ");
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_NEAR(std::stod(r.out.substr(at + 16)), 3.141592653589793, 1e-9) << method << "\n" << r.out;
  }
}

}  // namespace
