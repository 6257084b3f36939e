// rollspin — a ball rolling without slipping or spinning is a spin-1/2 in a
// magnetic field, with arc length as time. Entry point: parses the command
// line, runs one command, and maps errors to exit codes (2 bad input,
// 1 runtime failure).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "cli/cli_messages.hpp"
#include "cli/commands.hpp"
#include "cli/version_info.hpp"
#include "core/error.hpp"
#include "core/stage_log.hpp"
#include "core/temp_files.hpp"
#include "jobs/address_space.hpp"
#include "jobs/huge_pages.hpp"

namespace {

using rollspin::cli::CommandHandler;

// Every command, registered on the app; `handler` is set to the one chosen.
void registerCommands(CLI::App& cli, CommandHandler& handler) {
  rollspin::cli::registerSolveCommands(cli, handler);
  rollspin::cli::registerSceneCommand(cli, handler);
  rollspin::cli::registerRenderCommands(cli, handler);
  rollspin::cli::registerReportCommands(cli, handler);
  rollspin::cli::registerInfoCommand(cli, handler);
  rollspin::cli::registerJoinCommand(cli, handler);
  rollspin::cli::registerExportCommand(cli, handler);
  rollspin::cli::registerHelpCommands(cli, handler);
}

// --version needs no command: the release, the source's git describe, and
// with --verbose the GL backend a render would use. True when it was asked.
bool printedVersion(int argc, char** argv) {
  bool version = false, verboseToo = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    version = version || arg == "--version";
    verboseToo = verboseToo || arg == "--verbose" || arg == "-v";
  }
  if (!version) return false;
  std::printf("%s\n", rollspin::cli::versionLine().c_str());
  if (verboseToo) std::printf("GL backend: %s\n", rollspin::cli::glBackendDescription().c_str());
  return true;
}

// Names an unknown command instead of CLI11's generic "a subcommand is
// required". True when argv[1] is one.
bool refusedUnknownCommand(const CLI::App& cli, int argc, char** argv) {
  std::string known;
  bool isKnown = false;
  for (const CLI::App* sub : cli.get_subcommands({})) {
    known += (known.empty() ? "" : ", ") + sub->get_name();
    isKnown = isKnown || (argc > 1 && sub->get_name() == argv[1]);
  }
  if (argc <= 1 || argv[1][0] == '-' || isKnown) return false;
  std::fprintf(stderr, "rollspin: error: unknown command '%s'; commands: %s\n", argv[1], known.c_str());
  std::vector<std::string> names;
  for (const CLI::App* sub : cli.get_subcommands({})) names.push_back(sub->get_name());
  if (const std::string guess = rollspin::cli::nearestName(argv[1], names); !guess.empty())
    std::fprintf(stderr, "rollspin: did you mean '%s'?\n", guess.c_str());
  return true;
}

// The process around a command: huge pages for a render, the stage log, the
// address-space limit, and clean-up on a signal or a crash.
void prepareProcess(const CLI::App& cli, char** argv, bool verbose) {
  // A render restarts itself once, here, before it opens or writes anything,
  // so that malloc can use huge pages (see jobs/huge_pages.hpp).
  if (cli.got_subcommand("render")) rollspin::jobs::restartWithHugePages(argv);
  if (const char* tunables = std::getenv("GLIBC_TUNABLES"); rollspin::jobs::restartedForHugePages() && verbose)
    std::fprintf(stderr,
                 "rollspin: memory: restarted with GLIBC_TUNABLES=%s, so that malloc asks for transparent huge pages "
                 "(GLIBC_TUNABLES=glibc.malloc.hugetlb=0 keeps small pages)\n",
                 tunables != nullptr ? tunables : "");
  rollspin::StageLog::instance().setEcho(verbose);
  // Under ulimit -v: need less address space (see jobs/address_space.hpp).
  rollspin::jobs::fitToAddressSpaceLimit(verbose);
  // Ctrl-C or SIGTERM: remove unfinished outputs, say so, exit 128 + signal.
  rollspin::installInterruptCleanup();
  // A crash (glibc's heap checks included) says where, with a backtrace.
  rollspin::installCrashReport();
}

// Runs the command; errors become a message and an exit code.
int runCommand(const CommandHandler& handler) {
  try {
    return handler ? handler() : 2;
  } catch (const rollspin::Error& e) {
    std::fprintf(stderr, "rollspin: error: %s\n", rollspin::cli::withMemoryWayOut(e.what()).c_str());
    return e.exitCode();
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "rollspin: error: %s\n", rollspin::cli::withMemoryWayOut("out of memory").c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rollspin: internal error: %s\n", e.what());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"rollspin: the rolling sphere and the quantum spin"};
  cli.require_subcommand(1);
  // Global flags may also follow the subcommand: rollspin solve X --verbose.
  cli.fallthrough(true);
  bool verbose = false;
  cli.add_flag("-v,--verbose", verbose, "List the pipeline stages as they run");
  bool versionShown = false;  // handled before parsing (printedVersion); listed for --help
  cli.add_flag("--version", versionShown,
               "Print the version and git describe (with --verbose, the GL backend) and exit");
  CommandHandler handler;
  registerCommands(cli, handler);
  if (printedVersion(argc, argv)) return 0;
  if (refusedUnknownCommand(cli, argc, argv)) return 2;
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fputs(rollspin::cli::describeParseError(cli, e, argc, argv).c_str(), stderr);
    return 2;
  }
  prepareProcess(cli, argv, verbose);
  return runCommand(handler);
}
