#include "media/video_probe.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <fstream>
#include <memory>
#include <stdexcept>

namespace rollspin::test {

namespace {

std::string orEmpty(const char* s) { return s ? s : ""; }

// Top-level MP4 boxes in file order: size (4 bytes, big-endian), type (4).
bool moovBeforeMdat(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::uint64_t offset = 0;
  const auto total = std::filesystem::file_size(file);
  while (offset + 8 <= total) {
    unsigned char header[16];
    in.seekg(static_cast<std::streamoff>(offset));
    if (!in.read(reinterpret_cast<char*>(header), 8)) return false;
    std::uint64_t size = (std::uint64_t(header[0]) << 24) | (header[1] << 16) | (header[2] << 8) | header[3];
    const std::string type(reinterpret_cast<char*>(header) + 4, 4);
    if (size == 1) {
      if (!in.read(reinterpret_cast<char*>(header + 8), 8)) return false;
      size = 0;
      for (int i = 8; i < 16; ++i) size = (size << 8) | header[i];
    }
    if (type == "moov") return true;
    if (type == "mdat") return false;
    if (size < 8) return false;
    offset += size;
  }
  return false;
}

}  // namespace

VideoProbe probeVideo(const std::filesystem::path& file, const std::set<long long>& keepFrames) {
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, file.c_str(), nullptr, nullptr) < 0)
    throw std::runtime_error("cannot open " + file.string());
  std::unique_ptr<AVFormatContext, void (*)(AVFormatContext*)> formatGuard(
      format, [](AVFormatContext* f) { avformat_close_input(&f); });
  if (avformat_find_stream_info(format, nullptr) < 0) throw std::runtime_error("no stream info in " + file.string());
  const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (index < 0) throw std::runtime_error("no video stream in " + file.string());
  const AVStream* stream = format->streams[index];
  const AVCodecParameters* par = stream->codecpar;

  VideoProbe probe;
  probe.container = format->iformat->name;
  probe.codec = avcodec_get_name(par->codec_id);
  probe.pixelFormat = orEmpty(av_get_pix_fmt_name(static_cast<AVPixelFormat>(par->format)));
  probe.colorSpace = orEmpty(av_color_space_name(par->color_space));
  probe.colorPrimaries = orEmpty(av_color_primaries_name(par->color_primaries));
  probe.colorTransfer = orEmpty(av_color_transfer_name(par->color_trc));
  probe.colorRange = orEmpty(av_color_range_name(par->color_range));
  probe.chromaLocation = orEmpty(av_chroma_location_name(par->chroma_location));
  probe.width = par->width;
  probe.height = par->height;
  probe.frameRate = av_q2d(stream->avg_frame_rate);
  probe.frameRateNum = stream->avg_frame_rate.num;
  probe.frameRateDen = stream->avg_frame_rate.den;
  probe.timeBaseNum = stream->time_base.num;
  probe.timeBaseDen = stream->time_base.den;
  probe.durationTicks = stream->duration;
  probe.indexBeforeData = moovBeforeMdat(file);

  if (const AVDictionaryEntry* tag = av_dict_get(stream->metadata, "alpha_mode", nullptr, 0))
    probe.alphaMode = tag->value;
  if (const char* name = avcodec_profile_name(par->codec_id, par->profile)) probe.profile = name;
  probe.level = par->level;
  const AVCodec* decoder = par->codec_id == AV_CODEC_ID_VP9 && probe.alphaMode == "1"
                               ? avcodec_find_decoder_by_name("libvpx-vp9")
                               : avcodec_find_decoder(par->codec_id);
  if (decoder == nullptr) throw std::runtime_error("no decoder for " + probe.codec);
  AVCodecContext* codec = avcodec_alloc_context3(decoder);
  std::unique_ptr<AVCodecContext, void (*)(AVCodecContext*)> codecGuard(
      codec, [](AVCodecContext* c) { avcodec_free_context(&c); });
  avcodec_parameters_to_context(codec, par);
  codec->thread_count = 1;  // frames in presentation order, deterministic
  if (avcodec_open2(codec, decoder, nullptr) < 0) throw std::runtime_error("cannot open the decoder");

  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  SwsContext* sws = nullptr;
  long long decoded = 0;
  auto drain = [&] {
    while (avcodec_receive_frame(codec, frame) == 0) {
      probe.ptsSeconds.push_back(double(frame->best_effort_timestamp) * av_q2d(stream->time_base));
      probe.ptsTicks.push_back(frame->best_effort_timestamp);
      if (probe.decodedPixelFormat.empty())
        probe.decodedPixelFormat = orEmpty(av_get_pix_fmt_name(static_cast<AVPixelFormat>(frame->format)));
      if (keepFrames.contains(decoded)) {
        if (sws == nullptr) {
          sws = sws_getContext(frame->width, frame->height, static_cast<AVPixelFormat>(frame->format), frame->width,
                               frame->height, AV_PIX_FMT_RGBA, SWS_BILINEAR, nullptr, nullptr, nullptr);
          const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
          sws_setColorspaceDetails(sws, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
        }
        media::Image image(frame->width, frame->height);
        std::uint8_t* dst[1] = {image.rgba.data()};
        const int dstStride[1] = {frame->width * 4};
        sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, dstStride);
        probe.kept.push_back(std::move(image));
      }
      ++decoded;
      av_frame_unref(frame);
    }
  };
  while (av_read_frame(format, packet) >= 0) {
    if (packet->stream_index == index) {
      probe.packetDtsTicks.push_back(packet->dts);
      probe.packetPtsTicks.push_back(packet->pts);
      avcodec_send_packet(codec, packet);
      drain();
    }
    av_packet_unref(packet);
  }
  avcodec_send_packet(codec, nullptr);
  drain();
  sws_freeContext(sws);
  av_frame_free(&frame);
  av_packet_free(&packet);
  return probe;
}

}  // namespace rollspin::test
