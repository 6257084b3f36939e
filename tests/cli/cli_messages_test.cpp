// cli_messages in-process: CLI11's parse errors in rollspin's voice (range and
// conversion errors reworded, typos answered with the nearest option, the
// --help of the command that was searched), and the way out of "out of memory".
// The expected lines are written from cli_messages.hpp's promises; the errors
// come from a small CLI11 app parsed here, as main() parses the real one.
#include "cli/cli_messages.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/cli_runner.hpp"

namespace cli_messages_test {

using rollspin::test::has;

// A small app with the shapes rollspin's has: a global flag, a command with
// options, and a command with a subcommand.
struct SmallApp {
  CLI::App app{"rollspin: test"};
  bool verbose = false;
  double maxDelta = 0;
  int width = 0;
  std::vector<std::string> sets;
  SmallApp() {
    app.add_flag("-v,--verbose", verbose, "stages");
    CLI::App* render = app.add_subcommand("render", "render");
    render->add_option("--set", sets, "a key");
    render->add_option("--width", width, "pixels");
    CLI::App* report = app.add_subcommand("report", "report");
    CLI::App* errors = report->add_subcommand("errors", "errors");
    errors->add_option("--max-delta", maxDelta, "threshold")->check(CLI::Range(0.0, 255.0));
  }
};

// What describeParseError prints for `argv` (argv[0] included), or "" if it parsed.
std::string errorFor(std::vector<const char*> argv) {
  SmallApp s;
  try {
    s.app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    return rollspin::cli::describeParseError(s.app, e, static_cast<int>(argv.size()), argv.data());
  }
  return "";
}

TEST(CliMessages, RangeErrorNamesTheOptionTheRangeAndTheValueAndTheNestedCommandsHelp) {
  EXPECT_EQ(errorFor({"rollspin", "report", "errors", "--max-delta", "300"}),
            "rollspin: error: --max-delta: expected a number in [0, 255], got 300\n"
            "rollspin: see 'rollspin report errors --help'\n");
  // CLI11's range check also refuses what is no number at all: the same words.
  EXPECT_EQ(errorFor({"rollspin", "report", "errors", "--max-delta", "abc"}),
            "rollspin: error: --max-delta: expected a number in [0, 255], got abc\n"
            "rollspin: see 'rollspin report errors --help'\n");
}

TEST(CliMessages, ConversionErrorSaysANumberWasExpected) {
  EXPECT_EQ(errorFor({"rollspin", "render", "--width", "wide"}),
            "rollspin: error: --width: expected a number, got 'wide'\n"
            "rollspin: see 'rollspin render --help'\n");
}

TEST(CliMessages, ATypoIsAnsweredWithTheNearestOptionOfTheCommand) {
  EXPECT_EQ(errorFor({"rollspin", "render", "--sett"}),
            "rollspin: error: The following argument was not expected: --sett\n"
            "rollspin: '--sett': did you mean --set?\n"
            "rollspin: see 'rollspin render --help'\n");
}

TEST(CliMessages, ATypoWithAnEqualsSignIsLookedUpWithoutItsValue) {
  const std::string out = errorFor({"rollspin", "render", "--widht=3"});
  EXPECT_TRUE(has(out, "rollspin: '--widht': did you mean --width?\n")) << out;
}

TEST(CliMessages, GlobalOptionsAreCandidatesToo) {
  const std::string out = errorFor({"rollspin", "render", "--verbos"});
  EXPECT_TRUE(has(out, "rollspin: '--verbos': did you mean --verbose?\n")) << out;
}

TEST(CliMessages, EveryMistypedWordGetsItsOwnSuggestion) {
  const std::string out = errorFor({"rollspin", "render", "--sett", "x", "--widht", "3"});
  EXPECT_TRUE(has(out, "rollspin: '--sett': did you mean --set?\n")) << out;
  EXPECT_TRUE(has(out, "rollspin: '--widht': did you mean --width?\n")) << out;
  // Words without a dash are values, not options: nothing suggested for them.
  EXPECT_FALSE(has(out, "'x'")) << out;
  EXPECT_FALSE(has(out, "'3'")) << out;
}

TEST(CliMessages, NoSuggestionForAWordFarFromEveryOption) {
  const std::string out = errorFor({"rollspin", "render", "--zzzzzzzzzz"});
  EXPECT_FALSE(has(out, "did you mean")) << out;
  EXPECT_TRUE(out.starts_with("rollspin: error: ")) << out;
  EXPECT_TRUE(out.ends_with("rollspin: see 'rollspin render --help'\n")) << out;
}

TEST(CliMessages, AnOptionOfAnotherCommandIsNoCandidate) {
  // --max-delta belongs to `report errors`, not to `render`.
  const std::string out = errorFor({"rollspin", "render", "--max-delt", "3"});
  EXPECT_FALSE(has(out, "--max-delta")) << out;
}

TEST(CliMessages, WithoutACommandTheTopLevelHelpIsNamed) {
  const std::string out = errorFor({"rollspin", "--verbse"});
  EXPECT_TRUE(has(out, "rollspin: '--verbse': did you mean --verbose?\n")) << out;
  EXPECT_TRUE(out.ends_with("rollspin: see 'rollspin --help'\n")) << out;
}

TEST(CliMessages, EveryLineEndsInANewline) {
  const std::string out = errorFor({"rollspin", "render", "--sett", "x", "--widht", "3"});
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.back(), '\n');
  for (std::size_t at = 0; at < out.size();) {
    const std::size_t end = out.find('\n', at);
    ASSERT_NE(end, std::string::npos);
    EXPECT_TRUE(out.substr(at, end - at).starts_with("rollspin: ")) << out;
    at = end + 1;
  }
}

TEST(CliMessages, OutOfMemoryGetsAWayOut) {
  const std::string message = "frame 3: out of memory";
  const std::string out = rollspin::cli::withMemoryWayOut(message);
  EXPECT_TRUE(out.starts_with(message + "; ")) << out;
  EXPECT_TRUE(has(out, "--set render.msaa=1")) << out;
  EXPECT_TRUE(has(out, "--width/--height")) << out;
  EXPECT_TRUE(has(out, "ulimit -v")) << out;
}

TEST(CliMessages, AnyOtherMessageIsLeftAlone) {
  for (const std::string message : {"", "no such file", "out of range"})
    EXPECT_EQ(rollspin::cli::withMemoryWayOut(message), message);
}

}  // namespace cli_messages_test
