// The man page and the shell completions, generated from the CLI11 app
// itself (every command, option and description as --help shows them), so
// that they cannot fall behind the options. The build runs
// `rollspin generate man|bash|zsh` and installs the results.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace rollspin::cli {

// rollspin.1 in roff (man(7) macros).
[[nodiscard]] std::string manPage(const CLI::App& cli, const std::string& version);
// share/bash-completion/completions/rollspin: commands, options, scene names and files.
[[nodiscard]] std::string bashCompletion(const CLI::App& cli);
// share/zsh/site-functions/_rollspin (vendor-completions under /usr).
[[nodiscard]] std::string zshCompletion(const CLI::App& cli);

}  // namespace rollspin::cli
