// The commands that explain rollspin, end to end: `keys` (from the key
// registry), `scenes` (the bundled scenes with their descriptions), bare
// scene names, where a missing scene was looked for, "did you mean" for a
// misspelled scene key, --help naming every output format, and the
// generated man page and completions.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

#include "support/cli_runner.hpp"

namespace {

using rollspin::test::freshTempDir;
using rollspin::test::runRollspin;
using rollspin::test::sourceDir;

using rollspin::test::has;

TEST(KeysCommand, ListsAKeyWithItsDefaultAndMeaning) {
  const auto r = runRollspin({"keys", "ball"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(has(r.out, "ball.radius (number) = 1\n")) << r.out;
  EXPECT_TRUE(has(r.out, "the ball's radius R")) << r.out;
  EXPECT_FALSE(has(r.out, "render.width")) << "a section lists only its own keys";
  const auto all = runRollspin({"keys"});
  ASSERT_EQ(all.exitCode, 0) << all.err;
  EXPECT_TRUE(has(all.out, "render.width (integer) = 1280")) << all.out;
  EXPECT_TRUE(has(all.out, "allowed: [1, 8192]\n      units: pixels")) << all.out;
  EXPECT_TRUE(has(all.out, "path.colatitude_deg (number) = 60")) << all.out;
}

TEST(KeysCommand, MarkdownIsTheCommittedReference) {
  const auto r = runRollspin({"keys", "--markdown"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.out == rollspin::test::readFile(sourceDir() / "docs" / "scene-reference.md"))
      << "docs/scene-reference.md is stale; regenerate it with: build/rollspin keys --markdown > "
         "docs/scene-reference.md";
}

TEST(KeysCommand, AnUnknownSectionIsBadInputWithAGuess) {
  const auto r = runRollspin({"keys", "rendr"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "unknown section 'rendr' (did you mean 'render'?)")) << r.err;
}

TEST(ScenesCommand, ListsEveryBundledSceneWithOneLine) {
  const auto r = runRollspin({"scenes"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  int listed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(sourceDir() / "scenes")) {
    if (entry.path().extension() != ".toml") continue;
    ++listed;
    EXPECT_TRUE(has(r.out, entry.path().stem().string() + " ")) << entry.path() << " not listed:\n" << r.out;
  }
  EXPECT_GE(listed, 10);
  // The description is the first sentence of the file's leading comment, abbreviations kept.
  EXPECT_TRUE(has(r.out,
                  "The lollipop (Rojo & Bloch, sec. IV): a ball of radius R rolls once, counter-clockwise, "
                  "around a circle of radius r on the floor.\n"))
      << r.out;
  const auto names = runRollspin({"scenes", "--names"});
  ASSERT_EQ(names.exitCode, 0);
  EXPECT_TRUE(has(names.out, "lollipop\n")) << names.out;
  EXPECT_FALSE(has(names.out, " ")) << names.out;
}

TEST(SceneNames, ABareNameIsTheBundledSceneFromAnyDirectory) {
  const auto dir = freshTempDir("bare_scene_name");
  const auto byName = runRollspin({"solve", "lollipop", "--json"}, dir);
  ASSERT_EQ(byName.exitCode, 0) << byName.err;
  const auto byPath = runRollspin({"solve", (sourceDir() / "scenes" / "lollipop.toml").string(), "--json"}, dir);
  ASSERT_EQ(byPath.exitCode, 0) << byPath.err;
  // Same scene, same result (the timing line aside).
  auto withoutTiming = [](std::string s) { return s.substr(0, s.find("\"solve_seconds\"")); };
  EXPECT_EQ(withoutTiming(byName.out), withoutTiming(byPath.out));
  // A file of that name in the working directory wins over the bundled scene.
  std::ofstream(dir / "lollipop") << "[ball]\nradius = 0.5\n[path]\nradius = 2\n";
  const auto local = runRollspin({"scene", "lollipop", "--print"}, dir);
  ASSERT_EQ(local.exitCode, 0) << local.err;
  EXPECT_TRUE(has(local.out, "radius = 0.5")) << local.out;
  // $ROLLSPIN_SCENE_PATH comes before the bundled folder.
  std::filesystem::create_directories(dir / "mine");
  std::ofstream(dir / "mine" / "lollipop.toml") << "[ball]\nradius = 0.25\n";
  std::filesystem::create_directories(dir / "elsewhere");
  const auto fromEnv = runRollspin({"scene", "lollipop", "--print"}, dir / "elsewhere", 0,
                                   {"ROLLSPIN_SCENE_PATH=" + (dir / "mine").string()});
  ASSERT_EQ(fromEnv.exitCode, 0) << fromEnv.err;
  EXPECT_TRUE(has(fromEnv.out, "radius = 0.25")) << fromEnv.out;
}

TEST(SceneNames, AMissingSceneSaysWhereItLooked) {
  const auto dir = freshTempDir("missing_scene");
  const auto r = runRollspin({"render", "lolipop", "--still"}, dir, 0, {"ROLLSPIN_SCENE_PATH=/nonexistent/scenes"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "lolipop: cannot read the scene file: there is none; looked in the working directory (" +
                             std::filesystem::canonical(dir).string() + ")"))
      << r.err;
  EXPECT_TRUE(has(r.err, "/nonexistent/scenes")) << r.err;
  EXPECT_TRUE(has(r.err, (sourceDir() / "scenes").string())) << r.err;
  EXPECT_TRUE(has(r.err, "did you mean 'lollipop'?")) << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "nothing written";
}

TEST(SceneKeys, AMisspelledKeySaysDidYouMeanWithItsPlace) {
  const auto dir = freshTempDir("did_you_mean");
  std::ofstream(dir / "typo.toml") << "[ball]\nradius = 1\n\n[surface]\nkind = \"sphere\"\nradus = 3\n";
  const auto r = runRollspin({"solve", (dir / "typo.toml").string()});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(has(r.err, "typo.toml:6:9: surface.radus: unknown key; did you mean `radius`?")) << r.err;
  const auto set = runRollspin({"solve", "lollipop", "--set", "render.widht=640"});
  EXPECT_EQ(set.exitCode, 2);
  EXPECT_TRUE(has(set.err, "render.widht: unknown key; did you mean `width`?")) << set.err;
}

TEST(Help, RenderNamesEveryOutputFormat) {
  const auto r = runRollspin({"render", "--help"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* format : {"MP4", "WebM", "MOV", "GIF", "PNG frames", "JPEG", "PDF", "SVG"})
    EXPECT_TRUE(has(r.out, format)) << format << " missing from render --help:\n" << r.out;
  EXPECT_TRUE(has(r.out, "bundled scene")) << r.out;
}

// Every command the sources declare (`add_subcommand("name"` in src/cli/),
// read from the sources rather than from the CLI, so that a command left out
// of --help (as `generate` once was) cannot hide from the test.
std::set<std::string> declaredCommands() {
  std::set<std::string> names;
  const std::regex declared(R"re(add_subcommand\(\s*"([a-z-]+)")re");
  for (const auto& entry : std::filesystem::directory_iterator(sourceDir() / "src" / "cli")) {
    if (entry.path().extension() != ".cpp") continue;
    const std::string text = rollspin::test::readFile(entry.path());
    for (std::sregex_iterator m(text.begin(), text.end(), declared), end; m != end; ++m) names.insert((*m)[1]);
  }
  return names;
}

TEST(Help, EveryDeclaredCommandIsInHelpAndTheManPage) {
  const auto commands = declaredCommands();
  ASSERT_GE(commands.size(), 12u) << "the scan found too few commands: is src/cli/ still where they are declared?";
  const auto man = runRollspin({"generate", "man"});
  ASSERT_EQ(man.exitCode, 0) << man.err;
  std::string helps;  // the top-level --help and each command's own --help (for nested ones)
  const auto top = runRollspin({"--help"});
  ASSERT_EQ(top.exitCode, 0) << top.err;
  helps += top.out;
  for (const char* parent : {"report"}) helps += runRollspin({parent, "--help"}).out;
  for (const auto& command : commands) {
    EXPECT_TRUE(std::regex_search(helps, std::regex("\n  " + command + "\\s"))) << command << " missing from --help";
    EXPECT_TRUE(std::regex_search(man.out, std::regex("\\.SS \"rollspin ([a-z]+ )?" + command + "[ \"]")))
        << command << " missing from the man page";
  }
}

TEST(Help, ManPageAndCompletionsCoverEveryCommand) {
  const auto man = runRollspin({"generate", "man"});
  const auto bash = runRollspin({"generate", "bash"});
  const auto zsh = runRollspin({"generate", "zsh"});
  ASSERT_EQ(man.exitCode, 0) << man.err;
  ASSERT_EQ(bash.exitCode, 0) << bash.err;
  ASSERT_EQ(zsh.exitCode, 0) << zsh.err;
  EXPECT_TRUE(man.out.starts_with(".TH ROLLSPIN 1")) << man.out.substr(0, 200);
  for (const char* command :
       {"solve", "timeline", "scene", "render", "compare", "report", "info", "join", "export", "keys", "scenes"}) {
    EXPECT_TRUE(has(man.out, std::string(".SS \"rollspin ") + command)) << command;
    EXPECT_TRUE(has(bash.out, std::string("\"") + command + "\")")) << command;
    EXPECT_TRUE(has(zsh.out, std::string("(") + command + ") _rollspin_cmd_")) << command;
  }
  EXPECT_TRUE(has(man.out, "\\-\\-transparent")) << "render's options are listed";
  EXPECT_TRUE(has(bash.out, "scenes --names")) << "scene names are completed";
  EXPECT_TRUE(has(man.out, ".SS \"rollspin generate")) << "generate is listed like every command";
  // The completions parse (bash -n; zsh is not installed everywhere).
  const auto dir = freshTempDir("completion_syntax");
  std::ofstream(dir / "rollspin.bash") << bash.out;
  EXPECT_EQ(std::system(("bash -n " + (dir / "rollspin.bash").string()).c_str()), 0);
  std::ofstream(dir / "_rollspin") << zsh.out;
  if (std::system("command -v zsh > /dev/null") == 0) {
    EXPECT_EQ(std::system(("zsh -n " + (dir / "_rollspin").string()).c_str()), 0);
  }
}

}  // namespace
