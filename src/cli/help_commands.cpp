// The commands that explain rollspin itself: `keys` (the scene reference,
// from the key registry the loader validates with), `scenes` (the bundled
// scenes), and `generate`, which prints the man page and the shell
// completions (cli_reference.cpp): the build runs it, and so can a user
// who installs them by hand, so it is listed like every other command.
#include <fmt/format.h>

#include <memory>
#include <string>

#include "cli/cli_reference.hpp"
#include "cli/commands.hpp"
#include "core/error.hpp"
#include "scene/scene_catalog.hpp"
#include "scene/scene_keys.hpp"

namespace rollspin::cli {

namespace {

struct HelpOptions {
  std::string section;
  bool markdown = false;
  bool names = false;
  std::string what;
};

int runScenes(const HelpOptions& o) {
  const auto scenes = scene::bundledScenes();
  if (scenes.empty())
    throw Error(ErrorKind::Runtime, SourceLoc{"scenes"},
                "no bundled scenes found (looked for share/rollspin/scenes beside the executable and in "
                "$ROLLSPIN_SCENE_PATH)");
  std::size_t width = 0;
  for (const auto& s : scenes) width = std::max(width, s.name.size());
  for (const auto& s : scenes) {
    if (o.names) fmt::print("{}\n", s.name);
    else fmt::print("{:<{}}  {}\n", s.name, width, s.description);
  }
  if (!o.names)
    fmt::print("\nRun one with `rollspin render NAME --still` or `rollspin solve NAME`; folders: {}\n", [] {
      std::string list;
      for (const auto& f : scene::sceneFolders()) list += (list.empty() ? "" : ", ") + f.string();
      return list;
    }());
  return 0;
}

}  // namespace

void registerHelpCommands(CLI::App& cli, CommandHandler& handler) {
  auto options = std::make_shared<HelpOptions>();
  cli.footer(
      "SCENE: a TOML file, or a bundled scene's name (`rollspin scenes` lists them). Every scene key: "
      "`rollspin keys [SECTION]`. More: `man rollspin`, `rollspin COMMAND --help`.");

  CLI::App* keys =
      cli.add_subcommand("keys", "List every scene key with its default, allowed values, units and meaning");
  keys->add_option("section", options->section, "Only this table (ball, surface, path, render, animation, …)");
  keys->add_flag("--markdown", options->markdown, "Print the scene reference as Markdown (docs/scene-reference.md)");
  keys->callback([options, &handler] {
    handler = [options] {
      fmt::print("{}", options->markdown ? scene::keysMarkdown() : scene::keysText(options->section));
      return 0;
    };
  });

  CLI::App* scenes = cli.add_subcommand("scenes", "List the bundled scenes, one line each (run one by its name)");
  scenes->add_flag("--names", options->names, "Print the names only");
  scenes->callback([options, &handler] { handler = [options] { return runScenes(*options); }; });

  // Run by the build (src/cli/CMakeLists.txt) and listed in --help.
  CLI::App* generate = cli.add_subcommand(
      "generate", "Print the man page or a bash/zsh completion script (what `cmake --install` puts in place)");
  generate->add_option("what", options->what, "man | bash | zsh")
      ->required()
      ->check(CLI::IsMember({"man", "bash", "zsh"}));
  generate->callback([options, &cli, &handler] {
    handler = [options, &cli] {
      const std::string& w = options->what;
      fmt::print("{}", w == "man"    ? manPage(cli, ROLLSPIN_VERSION)
                       : w == "bash" ? bashCompletion(cli)
                                     : zshCompletion(cli));
      return 0;
    };
  });
}

}  // namespace rollspin::cli
