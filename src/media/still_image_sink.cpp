#include "media/still_image_sink.hpp"

#include "core/error.hpp"
#include "media/sink_factory.hpp"

namespace rollspin::media {

StillImageSink::StillImageSink(std::filesystem::path file, StillEncoding encoding, bool alpha, int jpegQuality,
                               std::optional<OutputMetadata> metadata)
    : file_(std::move(file)),
      encoding_(encoding),
      alpha_(alpha),
      jpegQuality_(jpegQuality),
      metadata_(std::move(metadata)) {}

void StillImageSink::write(const ImageView& frame) {
  if (image_) throw runtimeError(SourceLoc{file_.string()}, "a still image takes one frame");
  image_ = copyTopDown(frame);
}

std::filesystem::path StillImageSink::finish() {
  if (!image_) throw runtimeError(SourceLoc{file_.string()}, "no frame was rendered for the still");
  if (encoding_ == StillEncoding::Jpeg)
    writeJpeg(file_, image_->view(), jpegQuality_, metadata_ ? &*metadata_ : nullptr);
  else
    writePng(file_, image_->view(), alpha_ ? PngChannels::Rgba : PngChannels::Rgb, metadata_ ? &*metadata_ : nullptr);
  return file_;
}

std::unique_ptr<FrameSink> openPngStillSink(const SinkOptions& o) {
  return std::make_unique<StillImageSink>(o.path, StillEncoding::Png, o.alpha, o.jpegQuality, o.metadata);
}

std::unique_ptr<FrameSink> openJpegStillSink(const SinkOptions& o) {
  return std::make_unique<StillImageSink>(o.path, StillEncoding::Jpeg, false, o.jpegQuality, o.metadata);
}

}  // namespace rollspin::media
