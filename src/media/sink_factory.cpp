#include "media/sink_factory.hpp"

namespace rollspin::media {

namespace {

using SinkFactory = std::unique_ptr<FrameSink> (*)(const SinkOptions&);

// The table's factory column, in the table's row order.
#define ROLLSPIN_OUTPUT_FORMAT(name, extensions, kind, alpha, even, fpsCap, defaultWidth, shards, factory) &factory,
constexpr SinkFactory kSinkFactories[] = {
#include "media/output_formats.def"
};
#undef ROLLSPIN_OUTPUT_FORMAT
static_assert(std::size(kSinkFactories) == kOutputFormats.size());

}  // namespace

std::unique_ptr<FrameSink> noRasterSink(const SinkOptions& options) {
  throw runtimeError(SourceLoc{options.path.string()}, "this format is drawn as vectors and has no raster sink");
}

std::unique_ptr<FrameSink> openSink(const OutputFormat& format, const SinkOptions& options) {
  const auto row = static_cast<std::size_t>(&format - kOutputFormats.data());
  if (row >= kOutputFormats.size())
    throw runtimeError(SourceLoc{options.path.string()}, "output format '{}' is not a row of the table", format.name);
  return kSinkFactories[row](options);
}

}  // namespace rollspin::media
