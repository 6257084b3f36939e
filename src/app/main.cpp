// rollspin — a ball rolling without slipping or spinning is a spin-1/2 in a
// magnetic field, with arc length as time. Entry point: parses the command
// line, runs one command, and maps errors to exit codes (2 bad input,
// 1 runtime failure).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "core/stage_log.hpp"

int main(int argc, char** argv) {
  CLI::App cli{"rollspin: the rolling sphere and the quantum spin"};
  cli.require_subcommand(1);
  // Global flags may also follow the subcommand: rollspin solve X --verbose.
  cli.fallthrough(true);
  bool verbose = false;
  cli.add_flag("-v,--verbose", verbose, "List the pipeline stages as they run");
  rollspin::app::CommandHandler handler;
  rollspin::app::registerSolveCommands(cli, handler);
  rollspin::app::registerRenderCommands(cli, handler);
  rollspin::app::registerReportCommands(cli, handler);
  rollspin::app::registerInfoCommand(cli, handler);

  // Name an unknown command instead of CLI11's generic "a subcommand is required".
  std::string known;
  bool isKnown = false;
  for (const CLI::App* sub : cli.get_subcommands({})) {
    known += (known.empty() ? "" : ", ") + sub->get_name();
    isKnown = isKnown || (argc > 1 && sub->get_name() == argv[1]);
  }
  if (argc > 1 && argv[1][0] != '-' && !isKnown) {
    std::fprintf(stderr, "rollspin: error: unknown command '%s'; commands: %s\n", argv[1], known.c_str());
    return 2;
  }

  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    cli.exit(e);
    return 2;
  }

  rollspin::StageLog::instance().setEcho(verbose);
  try {
    return handler ? handler() : 2;
  } catch (const rollspin::Error& e) {
    std::fprintf(stderr, "rollspin: error: %s\n", e.what());
    return e.exitCode();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rollspin: internal error: %s\n", e.what());
    return 1;
  }
}
