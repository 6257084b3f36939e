// cli_reference in-process: the man page and the bash and zsh completions
// generated from a CLI11 app. cli_reference.hpp promises every command,
// option and description as --help shows them, hidden commands (empty group)
// left out. A small app written here pins the exact man(7) entries and the
// escaping; the real app (every register* of commands.hpp) is walked through
// CLI11's own objects: each visible command once, each of its options once.
#include "cli/cli_reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli/commands.hpp"
#include "support/cli_runner.hpp"

namespace cli_reference_test {

using rollspin::test::has;

// An app with a global flag, a command with a required positional, an option
// and a flag, a command with a subcommand, and a hidden command.
struct ReferenceApp {
  CLI::App app{"rollspin: the rolling sphere, for a test"};
  bool verbose = false, still = false, secret = false;
  std::string scene, output;
  std::vector<std::string> scenes;
  double delta = 0;
  ReferenceApp() {
    app.add_flag("-v,--verbose", verbose, "List the stages");
    CLI::App* render = app.add_subcommand("render", "Render the ball's still");
    render->add_option("scene", scene, "The scene to render")->required();
    render->add_option("-o,--output", output, "Where [the file] goes: a path");
    render->add_flag("--still", still, ".starts with a dot and a back\\slash");
    CLI::App* report = app.add_subcommand("report", "Write a report");
    CLI::App* errors = report->add_subcommand("errors", "The error report");
    errors->add_option("--max-delta", delta, "Largest difference\n.in radians\n'or none'");
    errors->add_option("scenes", scenes, "Scenes to compare");
    CLI::App* hidden = app.add_subcommand("secretcmd", "Hidden from the reference");
    hidden->group("");
    hidden->add_flag("--secretflag", secret, "A hidden flag");
  }
};

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The lines from `from` (a whole line) up to the next line starting with one
// of `ends` (or the end), without the first.
std::vector<std::string> blockAfter(const std::vector<std::string>& lines, const std::string& from,
                                    const std::vector<std::string>& ends) {
  std::vector<std::string> block;
  bool inside = false;
  for (const std::string& line : lines) {
    if (inside) {
      for (const std::string& e : ends)
        if (line.starts_with(e)) return block;
      block.push_back(line);
    } else if (line == from) {
      inside = true;
    }
  }
  return block;
}

// man(7): the tag line of each .TP entry in `block`.
std::vector<std::string> tags(const std::vector<std::string>& block) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i + 1 < block.size(); ++i)
    if (block[i] == ".TP") out.push_back(block[i + 1]);
  return out;
}

// roff spelling of an option name: every '-' escaped.
std::string roffName(const std::string& name) {
  std::string out;
  for (char c : name) out += c == '-' ? std::string("\\-") : std::string(1, c);
  return out;
}

// The tags in which the option name `name` ("--output") appears as a whole name.
int tagsNaming(const std::vector<std::string>& tagLines, const std::string& name) {
  const std::string spelled = roffName(name);
  int n = 0;
  for (const std::string& tag : tagLines)
    for (std::size_t at = tag.find(spelled); at != std::string::npos; at = tag.find(spelled, at + 1)) {
      const std::string after = tag.substr(at + spelled.size());
      const bool before = at == 0 || tag[at - 1] == ' ' || (at >= 2 && tag.compare(at - 2, 2, "fB") == 0);
      if (before && (after.empty() || after[0] == ',' || after[0] == ' ' || after.starts_with("\\f"))) ++n;
    }
  return n;
}

// The values of `key="..."` in the bash completion's case for `path`.
std::vector<std::string> bashWords(const std::string& bash, const std::string& path, const std::string& key) {
  const std::string head = "    \"" + path + "\")\n";
  const std::size_t at = bash.find(head);
  if (at == std::string::npos) return {"<no case for " + path + ">"};
  const std::size_t lineEnd = bash.find('\n', at + head.size());
  const std::string line = bash.substr(at + head.size(), lineEnd - at - head.size());
  const std::size_t start = line.find(key + "=\"");
  if (start == std::string::npos) return {"<no " + key + ">"};
  const std::size_t from = start + key.size() + 2;
  std::istringstream words(line.substr(from, line.find('"', from) - from));
  std::vector<std::string> out;
  for (std::string w; words >> w;) out.push_back(w);
  std::sort(out.begin(), out.end());
  return out;
}

// Every command of the real app, as the user types it, with its CLI11 object.
void visibleCommands(const CLI::App* app, const std::string& prefix,
                     std::vector<std::pair<std::string, const CLI::App*>>& out, std::vector<std::string>& hidden) {
  for (const CLI::App* sub : app->get_subcommands({})) {
    const std::string path = prefix.empty() ? sub->get_name() : prefix + " " + sub->get_name();
    if (sub->get_group().empty()) {
      hidden.push_back(path);
      continue;
    }
    out.emplace_back(path, sub);
    visibleCommands(sub, path, out, hidden);
  }
}

TEST(CliReference, ManPageHasItsSectionsOnceEachInOrder) {
  const ReferenceApp r;
  const std::string man = rollspin::cli::manPage(r.app, "1.2.3");
  EXPECT_TRUE(man.starts_with(".TH ROLLSPIN 1 ")) << man;
  EXPECT_TRUE(has(linesOf(man).front(), "\"rollspin 1.2.3\"")) << man;
  std::size_t last = 0;
  for (const char* section : {"NAME", "SYNOPSIS", "DESCRIPTION", "GLOBAL OPTIONS", "COMMANDS", "ENVIRONMENT", "FILES",
                              "EXIT STATUS", "SEE ALSO"}) {
    const std::string heading = std::string("\n.SH ") + section + "\n";
    EXPECT_EQ(count(man, heading), 1u) << section;
    const std::size_t at = man.find(heading);
    EXPECT_GT(at, last) << section << " out of order";
    last = at;
  }
  EXPECT_EQ(count(man, "\n.SH "), 9u) << man;
}

TEST(CliReference, ManPageNameIsTheAppDescriptionWithoutItsPrefix) {
  const ReferenceApp r;
  const std::string man = rollspin::cli::manPage(r.app, "1.2.3");
  EXPECT_TRUE(has(man, "\n.SH NAME\nrollspin \\- the rolling sphere, for a test\n")) << man;
}

TEST(CliReference, ManPageListsGlobalOptionsUnderTheirOwnSection) {
  const ReferenceApp r;
  const std::vector<std::string> lines = linesOf(rollspin::cli::manPage(r.app, "1.2.3"));
  const std::vector<std::string> global = blockAfter(lines, ".SH GLOBAL OPTIONS", {".SH "});
  const std::vector<std::string> t = tags(global);
  EXPECT_EQ(tagsNaming(t, "--verbose"), 1);
  EXPECT_EQ(tagsNaming(t, "-v"), 1);
  EXPECT_EQ(tagsNaming(t, "--help"), 1);
  EXPECT_EQ(tagsNaming(t, "--output"), 0);  // render's, not global
  const std::size_t entry = std::find(global.begin(), global.end(), ".B \\-v, \\-\\-verbose") - global.begin();
  ASSERT_LT(entry + 1, global.size());
  EXPECT_EQ(global[entry + 1], "List the stages");
}

TEST(CliReference, ManPageHasEachVisibleCommandOnceWithItsUsageInOrder) {
  const ReferenceApp r;
  const std::string man = rollspin::cli::manPage(r.app, "1.2.3");
  std::vector<std::string> subsections;
  for (const std::string& line : linesOf(man))
    if (line.starts_with(".SS ")) subsections.push_back(line);
  const std::vector<std::string> expected = {
      ".SS \"rollspin render SCENE [OPTIONS]\"",
      ".SS \"rollspin report [OPTIONS] COMMAND\"",
      ".SS \"rollspin report errors [SCENES...] [OPTIONS]\"",
  };
  EXPECT_EQ(subsections, expected) << man;
  EXPECT_FALSE(has(man, "secret")) << man;
}

TEST(CliReference, ManPageEntriesOfACommandNameItsPositionalsAndOptions) {
  const ReferenceApp r;
  const std::vector<std::string> lines = linesOf(rollspin::cli::manPage(r.app, "1.2.3"));
  const std::vector<std::string> render =
      blockAfter(lines, ".SS \"rollspin render SCENE [OPTIONS]\"", {".SS ", ".SH "});
  ASSERT_FALSE(render.empty());
  EXPECT_EQ(render.front(), "Render the ball's still");
  const std::vector<std::string> t = tags(render);
  EXPECT_EQ(std::count(t.begin(), t.end(), ".I scene"), 1);
  // An option that takes a value says so; a flag does not.
  EXPECT_EQ(std::count(t.begin(), t.end(), "\\fB\\-o, \\-\\-output \\fIVALUE\\fR\\fR"), 1)
      << ::testing::PrintToString(t);
  EXPECT_EQ(std::count(t.begin(), t.end(), "\\fB\\-\\-still\\fR"), 1) << ::testing::PrintToString(t);
  EXPECT_EQ(tagsNaming(t, "--max-delta"), 0);  // report errors' option
  const std::vector<std::string> errors =
      blockAfter(lines, ".SS \"rollspin report errors [SCENES...] [OPTIONS]\"", {".SS ", ".SH "});
  EXPECT_EQ(tagsNaming(tags(errors), "--max-delta"), 1) << ::testing::PrintToString(errors);
}

TEST(CliReference, ManPageEscapesRoffInDescriptions) {
  const ReferenceApp r;
  const std::string man = rollspin::cli::manPage(r.app, "1.2.3");
  // A leading '.' would be read as a macro, a backslash as an escape.
  EXPECT_TRUE(has(man, "\n\\&.starts with a dot and a back\\eslash\n")) << man;
  EXPECT_FALSE(has(man, "\n.starts with")) << man;
  // So would a line of a description that starts with '.' or '\''.
  EXPECT_TRUE(has(man, "Largest difference\n\\&.in radians\n\\&'or none'\n")) << man;
}

TEST(CliReference, RealAppManPageHasEveryVisibleCommandAndOptionOnce) {
  CLI::App cli{"rollspin: the rolling sphere and the quantum spin"};
  rollspin::cli::CommandHandler handler;
  rollspin::cli::registerSolveCommands(cli, handler);
  rollspin::cli::registerSceneCommand(cli, handler);
  rollspin::cli::registerRenderCommands(cli, handler);
  rollspin::cli::registerReportCommands(cli, handler);
  rollspin::cli::registerInfoCommand(cli, handler);
  rollspin::cli::registerJoinCommand(cli, handler);
  rollspin::cli::registerExportCommand(cli, handler);
  rollspin::cli::registerHelpCommands(cli, handler);
  std::vector<std::pair<std::string, const CLI::App*>> commands;
  std::vector<std::string> hidden;
  visibleCommands(&cli, "", commands, hidden);
  ASSERT_GE(commands.size(), 10u);  // solve, timeline, render, compare, report ..., keys, scenes, generate

  const std::string man = rollspin::cli::manPage(cli, "0.0.0");
  const std::vector<std::string> lines = linesOf(man);
  const std::string bash = rollspin::cli::bashCompletion(cli);
  const std::string zsh = rollspin::cli::zshCompletion(cli);
  for (const auto& [path, app] : commands) {
    std::string heading;
    int headings = 0;
    // `.SS "rollspin PATH` then the usage (upper case, brackets), not a longer path.
    const std::string start = ".SS \"rollspin " + roffName(path);
    for (const std::string& line : lines) {
      const std::string rest = line.starts_with(start) ? line.substr(start.size()) : "";
      if (rest == "\"" || (rest.size() > 1 && rest[0] == ' ' && !std::islower(static_cast<unsigned char>(rest[1])))) {
        heading = line;
        ++headings;
      }
    }
    EXPECT_EQ(headings, 1) << path;
    const std::vector<std::string> t = tags(blockAfter(lines, heading, {".SS ", ".SH "}));
    for (const CLI::Option* o : app->get_options()) {
      if (o->get_positional() || o->get_group().empty()) continue;
      for (const std::string& l : o->get_lnames()) EXPECT_EQ(tagsNaming(t, "--" + l), 1) << path << " --" << l;
      for (const std::string& s : o->get_snames()) EXPECT_EQ(tagsNaming(t, "-" + s), 1) << path << " -" << s;
    }
    EXPECT_EQ(count(bash, "\n    \"" + path + "\")\n"), 1u) << path;
    std::string fn = path;
    for (char& c : fn)
      if (c == ' ' || c == '-') c = '_';
    EXPECT_EQ(count(zsh, "\n_rollspin_cmd_" + fn + "() {\n"), 1u) << path;
  }
  for (const std::string& path : hidden) {
    EXPECT_FALSE(has(man, ".SS \"rollspin " + roffName(path))) << path;
    EXPECT_FALSE(has(bash, "\"" + path + "\")")) << path;
  }
}

TEST(CliReference, BashCompletionKnowsEachCommandsOptionsValuesAndScenes) {
  const ReferenceApp r;
  const std::string bash = rollspin::cli::bashCompletion(r.app);
  using Words = std::vector<std::string>;
  EXPECT_EQ(bashWords(bash, "render", "opts"), (Words{"--help", "--output", "--still", "-h", "-o"}));
  EXPECT_EQ(bashWords(bash, "render", "valued"), (Words{"--output", "-o"}));
  EXPECT_EQ(bashWords(bash, "render", "subs"), Words{});
  EXPECT_EQ(bashWords(bash, "report", "subs"), Words{"errors"});
  EXPECT_EQ(bashWords(bash, "report errors", "valued"), Words{"--max-delta"});
  // A positional named scene(s) completes scene names; a command without one does not.
  EXPECT_TRUE(has(bash, "    \"render\")\n      opts=")) << bash;
  EXPECT_TRUE(has(bash, "subs=\"\"; scene=1 ;;\n    \"report\")")) << bash;
  EXPECT_TRUE(has(bash, "subs=\"errors\"; scene=0 ;;")) << bash;
  EXPECT_TRUE(has(bash, "\"render\"|\"report\"|\"report errors\")")) << bash;
  EXPECT_FALSE(has(bash, "secret")) << bash;
  EXPECT_TRUE(bash.ends_with("\ncomplete -F _rollspin rollspin\n")) << bash;
}

TEST(CliReference, BashCompletionOffersTopCommandsAndGlobalOptionsFirst) {
  const ReferenceApp r;
  const std::string bash = rollspin::cli::bashCompletion(r.app);
  // The first word list offered: `compgen -W "WORDS"` with no command typed yet.
  const std::string marker = "compgen -W \"";
  const std::size_t at = bash.find(marker);
  ASSERT_NE(at, std::string::npos) << bash;
  const std::size_t from = at + marker.size();
  std::istringstream in(bash.substr(from, bash.find('"', from) - from));
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  std::sort(words.begin(), words.end());
  EXPECT_EQ(words, (std::vector<std::string>{"--help", "--verbose", "-h", "-v", "render", "report"}));
}

TEST(CliReference, ZshCompletionHasAFunctionPerCommandWithEscapedSpecs) {
  const ReferenceApp r;
  const std::string zsh = rollspin::cli::zshCompletion(r.app);
  EXPECT_TRUE(zsh.starts_with("#compdef rollspin\n")) << zsh;
  for (const char* fn : {"_rollspin_cmd_render() {", "_rollspin_cmd_report() {", "_rollspin_cmd_report_errors() {"})
    EXPECT_EQ(count(zsh, std::string("\n") + fn + "\n"), 1u) << fn;
  EXPECT_FALSE(has(zsh, "secret")) << zsh;
  // _arguments specs: ], : and ' may not appear in a description as written.
  EXPECT_TRUE(has(zsh, "'--output[Where (the file) goes - a path]:value:_files'")) << zsh;
  EXPECT_TRUE(has(zsh, "'render:Render the ball'\\''s still'")) << zsh;
  EXPECT_TRUE(has(zsh, "'--still[.starts with a dot and a back\\slash]' \\\n")) << zsh;
  EXPECT_TRUE(has(zsh, "'1:scene:_rollspin_scenes'")) << zsh;
  EXPECT_TRUE(has(zsh, "'*:scenes:_rollspin_scenes'")) << zsh;
  EXPECT_TRUE(has(zsh, "(errors) _rollspin_cmd_report_errors ;;")) << zsh;
  EXPECT_TRUE(has(zsh, "(render) _rollspin_cmd_render ;;")) << zsh;
  EXPECT_TRUE(zsh.ends_with("\n_rollspin \"$@\"\n")) << zsh;
}

}  // namespace cli_reference_test
