#include "cli/cli_messages.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <regex>
#include <sstream>

namespace rollspin::cli {

namespace {

// The (sub)command argv selects: rollspin report errors … → "report errors".
const CLI::App* chosenCommand(const CLI::App& cli, int argc, const char* const* argv, std::string& path) {
  const CLI::App* app = &cli;
  for (int i = 1; i < argc; ++i) {
    const std::string token = argv[i];
    if (token.starts_with("-")) continue;
    const CLI::App* next = nullptr;
    for (const CLI::App* sub : app->get_subcommands({}))
      if (sub->get_name() == token) next = sub;
    if (next == nullptr) break;
    app = next;
    path += (path.empty() ? "" : " ") + token;
  }
  return app;
}

std::vector<std::string> optionNames(const CLI::App& cli, const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::App* app : {&cli, &command})
    for (const CLI::Option* opt : app->get_options()) {
      for (const std::string& l : opt->get_lnames()) names.push_back("--" + l);
      for (const std::string& s : opt->get_snames()) names.push_back("-" + s);
    }
  return names;
}

}  // namespace

std::string describeParseError(const CLI::App& cli, const CLI::ParseError& error, int argc, const char* const* argv) {
  std::string path;
  const CLI::App* command = chosenCommand(cli, argc, argv, path);
  std::string message = error.what();
  // CLI11's range check and conversion errors, in the project's words.
  static const std::regex range(R"(^(\S+): Value (.*) not in range (\S+) to (\S+)$)");
  static const std::regex conversion(R"(^Could not convert: (\S+) = (.*)$)");
  std::smatch m;
  if (std::regex_match(message, m, range))
    message = fmt::format("{}: expected a number in [{:g}, {:g}], got {}", m[1].str(), std::stod(m[3].str()),
                          std::stod(m[4].str()), m[2].str());
  else if (std::regex_match(message, m, conversion))
    message = fmt::format("{}: expected a number, got '{}'", m[1].str(), m[2].str());
  std::string out = "rollspin: error: " + message + "\n";
  // Unexpected arguments: suggest the option each dash-word was probably meant to be.
  const std::string extras = "were not expected: ", extra = "was not expected: ";
  std::size_t at = message.find(extras);
  const std::size_t skip = at != std::string::npos ? extras.size() : extra.size();
  if (at == std::string::npos) at = message.find(extra);
  if (at != std::string::npos) {
    const std::vector<std::string> names = optionNames(cli, *command);
    std::istringstream words(message.substr(at + skip));
    for (std::string word; words >> word;) {
      if (!word.starts_with("-")) continue;
      const std::string typed = word.substr(0, word.find('='));
      const std::string guess = nearestName(typed, names);
      if (!guess.empty()) out += fmt::format("rollspin: '{}': did you mean {}?\n", typed, guess);
    }
  }
  out += fmt::format("rollspin: see 'rollspin {}{}--help'\n", path, path.empty() ? "" : " ");
  return out;
}

std::string withMemoryWayOut(const std::string& message) {
  if (message.find("out of memory") == std::string::npos) return message;
  return message +
         "; to need less, render with --set render.msaa=1 (no multisampling), a smaller size "
         "(--width/--height, or --quality low for a clip), or raise the limit (ulimit -v)";
}

}  // namespace rollspin::cli
