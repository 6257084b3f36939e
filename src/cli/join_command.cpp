// `rollspin join PARTS... -o OUT`: the parts of a split render (render
// --shard K/N) checked and joined into one clip by stream copy (media/join_parts).
#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "core/error.hpp"
#include "jobs/interrupt_guard.hpp"
#include "media/join_parts.hpp"

namespace rollspin::cli {

namespace {

struct JoinOptions {
  std::vector<std::string> parts;
  std::string output;
  std::string subtitles = "vtt";
  bool quiet = false;
};

int runJoin(const JoinOptions& o) {
  if (o.output.empty())
    throw badInput({"-o"}, "expected -o OUT, the joined clip's file name (e.g. -o output/clip.mp4)");
  const media::SidecarFormats sidecarFormats = media::parseSidecarFormats(o.subtitles, "--subtitles");
  const std::vector<std::filesystem::path> parts(o.parts.begin(), o.parts.end());
  // A Ctrl-C stops between packets and leaves nothing (not even the temporary file).
  const jobs::InterruptGuard interrupts;
  const media::JoinSummary s = media::joinParts(parts, o.output, [] { return jobs::InterruptGuard::received() != 0; });
  if (s.written.empty()) {
    std::fprintf(stderr, "rollspin: join interrupted: nothing written\n");
    return 128 + jobs::InterruptGuard::received();
  }
  // The whole clip's captions beside it, as a render of the whole clip writes them.
  media::SubtitleSidecars(s.written, sidecarFormats, s.cues, s.fpsNum, s.fpsDen).commit();
  if (!o.quiet)
    std::fprintf(stderr, "rollspin: joined %zu parts into %s: %lld frames, %dx%d @ %d/%d fps (stream copy)\n",
                 parts.size(), s.written.string().c_str(), s.frames, s.width, s.height, s.fpsNum, s.fpsDen);
  return 0;
}

}  // namespace

void registerJoinCommand(CLI::App& cli, CommandHandler& handler) {
  auto options = std::make_shared<JoinOptions>();
  CLI::App* join = cli.add_subcommand(
      "join",
      "Join the parts of a split render (render --shard K/N) into one clip: checked, stream copy, no re-encode");
  join->add_option("parts", options->parts, "The part files (any order), e.g. output/clip.part-*-of-8.mp4")->required();
  join->add_option("-o,--output", options->output, "The joined clip (same container as the parts)");
  join->add_option("--subtitles", options->subtitles,
                   "The joined clip's captions as files beside it: vtt (NAME.vtt, the default), srt (NAME.vtt "
                   "and NAME.srt) or none");
  join->add_flag("--quiet", options->quiet, "No summary line");
  join->callback([options, &handler] { handler = [options] { return runJoin(*options); }; });
}

}  // namespace rollspin::cli
