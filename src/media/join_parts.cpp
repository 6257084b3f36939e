#include "media/join_parts.hpp"

#include "media/av_library.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <system_error>

#include "core/error.hpp"
#include "core/temp_files.hpp"
#include "core/text.hpp"
#include "media/av_support.hpp"
#include "media/container_tags.hpp"

namespace rollspin::media {

namespace fs = std::filesystem;

namespace {

struct InputCloser {
  void operator()(AVFormatContext* c) const { avformat_close_input(&c); }
};
struct PacketFreer {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct ParametersFreer {
  void operator()(AVCodecParameters* p) const { avcodec_parameters_free(&p); }
};
using Input = std::unique_ptr<AVFormatContext, InputCloser>;
using Packet = std::unique_ptr<AVPacket, PacketFreer>;

// A caption as the part's track holds it: its frames and its packet's bytes.
struct InBandCue {
  SubtitleCue cue;
  std::string payload;
};

// What pass 1 learns about one part; pass 2 copies its packets.
struct Part {
  fs::path path;
  std::string name;  // as given on the command line, for messages
  std::string extension;
  ContainerTags tags;
  std::map<std::string, std::string> metadata;  // every tag (the scene a part remembers, jobs/remembered_output.hpp)
  std::unique_ptr<AVCodecParameters, ParametersFreer> codec;
  std::unique_ptr<AVCodecParameters, ParametersFreer> subtitleCodec;  // null: no subtitle track
  std::vector<InBandCue> cues;                                        // the part's captions, in its own frames
  AVRational timeBase{0, 1}, frameRate{0, 1};
  long long packets = 0;
  std::int64_t firstPts = 0;  // the smallest presentation timestamp
  // The encoder's reorder (B-frame) delay: the first packet's presentation
  // less its decoding time, in ticks (0 where the container keeps no DTS).
  std::int64_t decodeDelay = 0;
  bool startsWithKeyframe = false;

  [[nodiscard]] SourceLoc loc() const { return SourceLoc{name}; }
  [[nodiscard]] std::string range() const { return fmt::format("frames {}-{}", tags.firstFrame, tags.lastFrame); }
};

// Opens a part and checks it holds one video stream (stream 0) and at most
// one subtitle stream (stream 1).
Input openPart(const fs::path& path, const SourceLoc& loc) {
  AVFormatContext* raw = nullptr;
  // "file:" keeps a colon in a file name from reading as a protocol.
  const std::string url = "file:" + path.string();
  if (const int ret = avformat_open_input(&raw, url.c_str(), nullptr, nullptr); ret < 0)
    throw badInput(loc, "cannot open this part: {}", av::errorText(ret));
  Input input(raw);
  if (const int ret = avformat_find_stream_info(input.get(), nullptr); ret < 0)
    throw badInput(loc, "cannot read this part's streams: {}", av::errorText(ret));
  const bool subtitles = input->nb_streams == 2 && input->streams[1]->codecpar->codec_type == AVMEDIA_TYPE_SUBTITLE;
  if ((input->nb_streams != 1 && !subtitles) || input->streams[0]->codecpar->codec_type != AVMEDIA_TYPE_VIDEO)
    throw badInput(loc,
                   "expected one video stream and at most one subtitle track (a part rendered by rollspin), "
                   "found {} stream(s)",
                   input->nb_streams);
  return input;
}

std::map<std::string, std::string> metadataOf(const AVFormatContext& input) {
  std::map<std::string, std::string> out;
  const AVDictionaryEntry* e = nullptr;
  // Matroska (WebM) stores tag names in upper case.
  while ((e = av_dict_get(input.metadata, "", e, AV_DICT_IGNORE_SUFFIX)) != nullptr)
    out[asciiLowercase(e->key)] = e->value;
  return out;
}

// A subtitle packet's cue, its times in whole frames: cues start and end on
// frames, so rounding to the nearest frame undoes the container's rounding
// (WebM keeps milliseconds).
InBandCue captionOf(const AVPacket& packet, const AVStream& stream, AVRational frameDuration) {
  InBandCue c;
  c.payload.assign(reinterpret_cast<const char*>(packet.data), static_cast<std::size_t>(packet.size));
  c.cue.firstFrame = av_rescale_q(packet.pts, stream.time_base, frameDuration);
  c.cue.endFrame = av_rescale_q(packet.pts + packet.duration, stream.time_base, frameDuration);
  c.cue.text = cueTextOfPacket(c.payload, stream.codecpar->codec_id == AV_CODEC_ID_MOV_TEXT);
  return c;
}

// Pass 1: the tags, the codec, and every packet's timestamp (no decoding).
Part inspectPart(const fs::path& path) {
  Part part;
  part.path = path;
  part.name = path.string();
  part.extension = asciiLowercase(path.extension().string());
  const Input input = openPart(path, part.loc());
  std::string why;
  part.metadata = metadataOf(*input);
  const auto tags = parseContainerTags(part.metadata, &why);
  if (!tags) throw badInput(part.loc(), "{}; render parts with `rollspin render --shard K/N` (or --frames A:B)", why);
  part.tags = *tags;

  const AVStream& stream = *input->streams[0];
  part.codec.reset(avcodec_parameters_alloc());
  if (!part.codec || avcodec_parameters_copy(part.codec.get(), stream.codecpar) < 0) throw std::bad_alloc();
  part.timeBase = stream.time_base;
  part.frameRate = stream.avg_frame_rate.num > 0 ? stream.avg_frame_rate : stream.r_frame_rate;
  if (part.frameRate.num <= 0 || part.frameRate.den <= 0)
    throw badInput(part.loc(), "its video stream states no frame rate");

  const AVStream* subtitles = input->nb_streams == 2 ? input->streams[1] : nullptr;
  if (subtitles != nullptr) {
    part.subtitleCodec.reset(avcodec_parameters_alloc());
    if (!part.subtitleCodec || avcodec_parameters_copy(part.subtitleCodec.get(), subtitles->codecpar) < 0)
      throw std::bad_alloc();
  }
  const AVRational frameDuration = av_inv_q(part.frameRate);

  std::vector<std::int64_t> pts;
  const Packet packet(av_packet_alloc());
  if (!packet) throw std::bad_alloc();
  int ret = 0;
  while ((ret = av_read_frame(input.get(), packet.get())) >= 0) {
    if (subtitles != nullptr && packet->stream_index == subtitles->index) {
      part.cues.push_back(captionOf(*packet, *subtitles, frameDuration));
      av_packet_unref(packet.get());
      if (part.cues.back().cue.text.empty()) part.cues.pop_back();  // MP4's filler between captions
      continue;
    }
    if (pts.empty()) {
      part.startsWithKeyframe = (packet->flags & AV_PKT_FLAG_KEY) != 0;
      if (packet->pts != AV_NOPTS_VALUE && packet->dts != AV_NOPTS_VALUE) part.decodeDelay = packet->pts - packet->dts;
    }
    const std::int64_t t = packet->pts;
    av_packet_unref(packet.get());
    if (t == AV_NOPTS_VALUE) throw badInput(part.loc(), "packet {} has no presentation timestamp", pts.size());
    pts.push_back(t);
  }
  if (ret != AVERROR_EOF) throw badInput(part.loc(), "cannot read this part to its end: {}", av::errorText(ret));
  part.packets = static_cast<long long>(pts.size());
  if (pts.empty()) throw badInput(part.loc(), "this part holds no frames");
  // A whole render puts frame k at k frame durations: the part's frames must
  // sit exactly so from its first one, or the joined timeline would not be.
  std::sort(pts.begin(), pts.end());
  part.firstPts = pts.front();
  for (std::size_t k = 0; k < pts.size(); ++k)
    if (pts[k] - pts.front() != av_rescale_q(static_cast<std::int64_t>(k), frameDuration, part.timeBase))
      throw badInput(part.loc(), "its frame {} is at tick {} of {}/{} s, expected {} (one frame every {}/{} s)", k,
                     pts[k] - pts.front(), part.timeBase.num, part.timeBase.den,
                     av_rescale_q(static_cast<std::int64_t>(k), frameDuration, part.timeBase), frameDuration.num,
                     frameDuration.den);
  return part;
}

std::string hexPrefix(const std::string& hash) { return hash.substr(0, 12) + "…"; }

// Everything that must be the same in every part, against the first one given.
void expectSameRender(const Part& p, const Part& ref) {
  const std::string& r = ref.name;
  if (p.extension != ref.extension)
    throw badInput(p.loc(), "is a '{}' file, but {} is '{}': join copies the streams into one container", p.extension,
                   r, ref.extension);
  if (p.tags.version != ref.tags.version)
    throw badInput(p.loc(), "was rendered by rollspin {}, but {} by rollspin {}: render every part with one version",
                   p.tags.version, r, ref.tags.version);
  if (p.codec->width != ref.codec->width || p.codec->height != ref.codec->height)
    throw badInput(p.loc(), "is {}x{}, but {} is {}x{}: every part of a clip has its size", p.codec->width,
                   p.codec->height, r, ref.codec->width, ref.codec->height);
  if (p.tags.encoderSettings != ref.tags.encoderSettings)
    throw badInput(p.loc(), "was encoded with '{}', but {} with '{}'", p.tags.encoderSettings, r,
                   ref.tags.encoderSettings);
  if (p.tags.sceneSha256 != ref.tags.sceneSha256)
    throw badInput(p.loc(),
                   "comes from a different scene than {} (SHA-256 of the resolved scene {} vs {}): render every part "
                   "from the same scene file and --set options (compare `rollspin scene SCENE --print`)",
                   r, hexPrefix(p.tags.sceneSha256), hexPrefix(ref.tags.sceneSha256));
  if (p.tags.clipFrames != ref.tags.clipFrames)
    throw badInput(p.loc(), "is a part of a {}-frame clip, but {} of a {}-frame one", p.tags.clipFrames, r,
                   ref.tags.clipFrames);
  if (p.codec->codec_id != ref.codec->codec_id || p.codec->format != ref.codec->format)
    throw badInput(p.loc(), "its codec ({}, {}) differs from {}'s ({}, {})", avcodec_get_name(p.codec->codec_id),
                   p.codec->format, r, avcodec_get_name(ref.codec->codec_id), ref.codec->format);
  if (p.codec->extradata_size != ref.codec->extradata_size ||
      (p.codec->extradata_size > 0 &&
       std::memcmp(p.codec->extradata, ref.codec->extradata, static_cast<std::size_t>(p.codec->extradata_size)) != 0))
    throw badInput(p.loc(),
                   "its codec extradata ({} bytes: the SPS/PPS) differ from {}'s ({} bytes): the parts were "
                   "not encoded alike, and one decoder could not play them in one stream",
                   p.codec->extradata_size, r, ref.codec->extradata_size);
  if (av_cmp_q(p.timeBase, ref.timeBase) != 0 || av_cmp_q(p.frameRate, ref.frameRate) != 0)
    throw badInput(p.loc(), "its time base {}/{} at {}/{} fps differs from {}'s {}/{} at {}/{} fps", p.timeBase.num,
                   p.timeBase.den, p.frameRate.num, p.frameRate.den, r, ref.timeBase.num, ref.timeBase.den,
                   ref.frameRate.num, ref.frameRate.den);
}

// Captions: all parts have a subtitle track of one codec, or none has.
void expectSameCaptions(const Part& p, const Part& ref) {
  const auto codecName = [](const Part& part) {
    return part.subtitleCodec ? fmt::format("a {} subtitle track", avcodec_get_name(part.subtitleCodec->codec_id))
                              : std::string("no subtitle track");
  };
  if (codecName(p) != codecName(ref))
    throw badInput(p.loc(), "has {}, but {} has {}: render every part with one rollspin and scene", codecName(p),
                   ref.name, codecName(ref));
}

// The parts' captions on the clip's frames, a cue that a part boundary cut
// in two made one again.
std::vector<InBandCue> clipCaptions(const std::vector<const Part*>& sorted) {
  std::vector<InBandCue> out;
  for (const Part* part : sorted)
    for (InBandCue c : part->cues) {
      c.cue.firstFrame += part->tags.firstFrame;
      c.cue.endFrame += part->tags.firstFrame;
      if (!out.empty() && out.back().cue.endFrame == c.cue.firstFrame && out.back().payload == c.payload)
        out.back().cue.endFrame = c.cue.endFrame;
      else out.push_back(std::move(c));
    }
  return out;
}

// The joined clip's subtitle stream (when the parts have one): each caption
// is written as the first frame it covers is (writeUpTo that frame).
class CaptionCopier {
 public:
  CaptionCopier(AVFormatContext* format, const Part& ref, std::vector<InBandCue> captions, AVRational frameDuration,
                SourceLoc where)
      : format_(format), captions_(std::move(captions)), frameDuration_(frameDuration), where_(std::move(where)) {
    if (!ref.subtitleCodec) return;
    stream_ = avformat_new_stream(format, nullptr);
    packet_.reset(av_packet_alloc());
    if (stream_ == nullptr || !packet_ || avcodec_parameters_copy(stream_->codecpar, ref.subtitleCodec.get()) < 0)
      throw std::bad_alloc();
    stream_->codecpar->codec_tag = 0;  // the muxer's tag for its container
    stream_->time_base = frameDuration;
  }

  void writeUpTo(std::int64_t frame) {
    for (; stream_ != nullptr && next_ < captions_.size() && captions_[next_].cue.firstFrame <= frame; ++next_) {
      const InBandCue& c = captions_[next_];
      check(av_new_packet(packet_.get(), static_cast<int>(c.payload.size())), "copying a caption");
      std::memcpy(packet_->data, c.payload.data(), c.payload.size());
      packet_->pts = packet_->dts = c.cue.firstFrame;
      packet_->duration = c.cue.endFrame - c.cue.firstFrame;
      packet_->flags |= AV_PKT_FLAG_KEY;
      packet_->stream_index = stream_->index;
      av_packet_rescale_ts(packet_.get(), frameDuration_, stream_->time_base);
      check(av_interleaved_write_frame(format_, packet_.get()), "writing a caption");
    }
  }

  [[nodiscard]] SubtitleCues cues() const {
    SubtitleCues out;
    for (const InBandCue& c : captions_) out.push_back(c.cue);
    return out;
  }

 private:
  void check(int ret, const char* what) const {
    if (ret < 0) throw runtimeError(where_, "{}: {}", what, av::errorText(ret));
  }
  AVFormatContext* format_;
  std::vector<InBandCue> captions_;
  AVRational frameDuration_;
  SourceLoc where_;
  AVStream* stream_ = nullptr;
  Packet packet_;
  std::size_t next_ = 0;
};

void expectWholePart(const Part& p) {
  if (p.packets != p.tags.frameCount())
    throw badInput(p.loc(), "holds {} frames, but its tags say {} ({} frames): an interrupted or damaged part",
                   p.packets, p.range(), p.tags.frameCount());
  if (!p.startsWithKeyframe) throw badInput(p.loc(), "does not start with a keyframe: a decoder could not begin there");
}

// Sorted by first frame, the ranges must tile 0 … total − 1.
void expectContiguous(const std::vector<const Part*>& sorted) {
  const Part& first = *sorted.front();
  const long long total = first.tags.clipFrames;
  if (first.tags.firstFrame != 0)
    throw badInput(first.loc(), "frames 0-{} of the {}-frame clip are missing: the earliest part given holds {}",
                   first.tags.firstFrame - 1, total, first.range());
  for (std::size_t k = 1; k < sorted.size(); ++k) {
    const Part& prev = *sorted[k - 1];
    const Part& cur = *sorted[k];
    std::error_code ec;
    if (fs::equivalent(prev.path, cur.path, ec)) throw badInput(cur.loc(), "is given twice");
    if (cur.tags.firstFrame > prev.tags.lastFrame + 1)
      throw badInput(cur.loc(), "frames {}-{} are missing between {} ({}) and this part ({})", prev.tags.lastFrame + 1,
                     cur.tags.firstFrame - 1, prev.name, prev.range(), cur.range());
    if (cur.tags.firstFrame <= prev.tags.lastFrame)
      throw badInput(cur.loc(), "overlaps {} at frames {}-{} (this part: {}; that one: {})", prev.name,
                     cur.tags.firstFrame, std::min(prev.tags.lastFrame, cur.tags.lastFrame), cur.range(), prev.range());
  }
  const Part& last = *sorted.back();
  if (last.tags.lastFrame != total - 1)
    throw badInput(last.loc(), "frames {}-{} of the {}-frame clip are missing: the latest part given holds {}",
                   last.tags.lastFrame + 1, total - 1, total, last.range());
}

// The output under construction: closed, freed and (unless committed)
// removed on every way out.
struct Output {
  AVFormatContext* format = nullptr;
  fs::path writePath;
  bool direct = false, opened = false, committed = false, registered = false;
  ~Output() {
    if (format != nullptr) {
      if (format->pb != nullptr) avio_closep(&format->pb);
      avformat_free_context(format);
    }
    if (opened && !committed && !direct) {
      std::error_code ec;
      fs::remove(writePath, ec);
    }
    if (registered) unregisterTemporary(writePath);
  }
};

// A libav error, or a write error the output's I/O context holds, as rollspin's error.
void checkJoinStep(const Output& out, const SourceLoc& where, int ret, const std::string& what) {
  if (ret < 0) throw runtimeError(where, "{}: {}", what, av::errorText(ret));
  if (out.format != nullptr && out.format->pb != nullptr && out.format->pb->error < 0)
    throw runtimeError(where, "{}: {}", what, av::errorText(out.format->pb->error));
}

// Pass 1: read every part's tags and timestamps. False when stopped.
bool inspectAllParts(const std::vector<fs::path>& paths, const fs::path& output, const SourceLoc& outLoc,
                     const std::function<bool()>& stop, std::vector<Part>& parts) {
  parts.reserve(paths.size());
  for (const fs::path& p : paths) {
    std::error_code ec;
    if (fs::is_directory(p, ec))
      throw badInput(SourceLoc{p.string()},
                     "is a folder: PNG frames of a split render already land side by side in one folder "
                     "(frame_NNNNN.png keeps its index in the clip); join takes video parts");
    if (!output.empty() && fs::equivalent(p, output, ec))
      throw badInput(outLoc, "is one of the parts; join writes a new file");
    parts.push_back(inspectPart(p));
    if (stop && stop()) return false;
  }
  return true;
}

// The parts checked against the first (one render, whole parts) and sorted
// into the clip's order, where they must tile it.
std::vector<const Part*> partsInClipOrder(const std::vector<Part>& parts) {
  const Part& ref = parts.front();
  for (const Part& p : parts) {
    expectSameRender(p, ref);
    expectSameCaptions(p, ref);
    expectWholePart(p);
  }
  std::vector<const Part*> sorted;
  for (const Part& p : parts) sorted.push_back(&p);
  std::stable_sort(sorted.begin(), sorted.end(), [](const Part* a, const Part* b) {
    return a->tags.firstFrame != b->tags.firstFrame ? a->tags.firstFrame < b->tags.firstFrame
                                                    : a->tags.lastFrame < b->tags.lastFrame;
  });
  expectContiguous(sorted);
  return sorted;
}

// Streams are copied, not re-encoded: the clip is in the parts' container.
const AVOutputFormat* joinedContainer(const Output& out, const fs::path& output, const Part& ref,
                                      const SourceLoc& outLoc) {
  if (!out.direct && asciiLowercase(output.extension().string()) != ref.extension)
    throw badInput(outLoc,
                   "the parts are '{}' files, so the joined clip must be one too (streams are copied, not "
                   "re-encoded)",
                   ref.extension);
  const AVOutputFormat* container = av_guess_format(nullptr, ("clip" + ref.extension).c_str(), nullptr);
  if (container == nullptr) throw badInput(outLoc, "libavformat has no muxer for '{}'", ref.extension);
  return container;
}

// The muxer and its video stream, with the parts' codec parameters.
AVStream* createJoinMuxer(Output& out, const AVOutputFormat* container, const std::string& url, const Part& ref,
                          const SourceLoc& where) {
  checkJoinStep(out, where, avformat_alloc_output_context2(&out.format, container, nullptr, url.c_str()),
                "creating the muxer");
  AVStream* stream = avformat_new_stream(out.format, nullptr);
  if (stream == nullptr) throw std::bad_alloc();
  checkJoinStep(out, where, avcodec_parameters_copy(stream->codecpar, ref.codec.get()), "configuring the stream");
  stream->codecpar->codec_tag = 0;  // let the muxer choose the tag for its container
  stream->time_base = ref.timeBase;
  stream->avg_frame_rate = ref.frameRate;
  return stream;
}

// What the parts remember (their scene, description, job) goes on; the
// job then holds the whole clip, so its "frames:" line (a part's) goes.
void copyRememberedMetadata(AVFormatContext* format, const Part& ref) {
  for (const auto& [key, value] : ref.metadata) {
    if (key.rfind("rollspin_", 0) == 0 && av_dict_get(format->metadata, key.c_str(), nullptr, 0) != nullptr) continue;
    std::string kept;
    for (std::size_t at = 0; at < value.size();) {
      const std::size_t end = std::min(value.find('\n', at), value.size());
      if (key != "rollspin_job" || value.compare(at, 8, "frames: ") != 0) kept += value.substr(at, end - at + 1);
      at = end + 1;
    }
    if (key != "encoder" && key != "major_brand" && key != "minor_version" && key != "compatible_brands")
      av_dict_set(&format->metadata, key.c_str(), kept.c_str(), 0);
  }
}

// The whole render's tags and the parts' metadata, then the file and its header.
void writeJoinedHeader(Output& out, const ContainerTags& whole, const Part& ref, const std::string& url,
                       const SourceLoc& where) {
  AVDictionary* options = nullptr;
  if (av_opt_find(out.format->priv_data, "movflags", nullptr, 0, 0) != nullptr)
    av_dict_set(&options, "movflags", out.direct ? "+write_colr" : "+faststart+write_colr", 0);
  applyContainerTags(out.format, whole, &options);
  copyRememberedMetadata(out.format, ref);
  if (const int ret = avio_open(&out.format->pb, url.c_str(), AVIO_FLAG_WRITE); ret < 0) {
    av_dict_free(&options);
    out.format->pb = nullptr;
    throw runtimeError(where, "cannot create {}: {}", out.writePath.string(), av::errorText(ret));
  }
  out.opened = true;
  const int headerRet = avformat_write_header(out.format, &options);
  av_dict_free(&options);
  checkJoinStep(out, where, headerRet, "writing the header");
}

// Pass 2: copy the packets, each moved to its frame's index in the clip.
// Decoding timestamps move with their packet, and a part encoded with less
// reorder delay than the clip's (the largest of the parts': x264 gives a
// short part none) moves them earlier by the difference: so they run on one
// frame a packet across the joins, and none comes after its presentation
// (checked: they must rise). False when stopped.
bool copyPartPackets(const std::vector<const Part*>& sorted, const Part& ref, Output& out, const AVStream* stream,
                     CaptionCopier& captions, const SourceLoc& where, const std::function<bool()>& stop) {
  const AVRational frameDuration = av_inv_q(ref.frameRate);
  std::int64_t clipDelay = 0;
  for (const Part* part : sorted) clipDelay = std::max(clipDelay, part->decodeDelay);
  std::int64_t lastDts = std::numeric_limits<std::int64_t>::min();
  const Packet packet(av_packet_alloc());
  if (!packet) throw std::bad_alloc();
  for (const Part* part : sorted) {
    const Input input = openPart(part->path, part->loc());
    int ret = 0;
    while ((ret = av_read_frame(input.get(), packet.get())) >= 0) {
      if (stop && stop()) {
        av_packet_unref(packet.get());
        return false;
      }
      if (packet->stream_index != 0) {  // the part's captions: written from `captions`
        av_packet_unref(packet.get());
        continue;
      }
      // The packet's frame in the part, then in the clip, then its tick:
      // exact where a frame is a whole number of ticks (MP4), and rounded
      // as a single render rounds it where not (WebM's milliseconds).
      const std::int64_t frameInPart = av_rescale_q(packet->pts - part->firstPts, ref.timeBase, frameDuration);
      captions.writeUpTo(part->tags.firstFrame + frameInPart);
      const std::int64_t pts = av_rescale_q(part->tags.firstFrame + frameInPart, frameDuration, ref.timeBase);
      const std::int64_t shift = pts - packet->pts;
      packet->pts = pts;
      if (packet->dts != AV_NOPTS_VALUE) {
        packet->dts += shift - (clipDelay - part->decodeDelay);
        if (packet->dts <= lastDts) {
          av_packet_unref(packet.get());
          throw badInput(part->loc(),
                         "its decoding order runs back into the previous part's: the parts were not encoded alike");
        }
        lastDts = packet->dts;
      }
      packet->stream_index = stream->index;
      packet->pos = -1;
      av_packet_rescale_ts(packet.get(), ref.timeBase, stream->time_base);
      ret = av_interleaved_write_frame(out.format, packet.get());  // takes the packet's reference
      checkJoinStep(out, where, ret, "writing " + out.writePath.string());
    }
    if (ret != AVERROR_EOF) throw runtimeError(part->loc(), "cannot read this part again: {}", av::errorText(ret));
  }
  return true;
}

// The trailer, then the temporary file renamed into place.
void finishJoinedFile(Output& out, const fs::path& output, const SourceLoc& where) {
  checkJoinStep(out, where, av_write_trailer(out.format), "finishing " + out.writePath.string());
  avio_flush(out.format->pb);
  checkJoinStep(out, where, 0, "finishing " + out.writePath.string());
  checkJoinStep(out, where, avio_closep(&out.format->pb), "closing " + out.writePath.string());
  if (!out.direct) {
    std::error_code ec;
    fs::rename(out.writePath, output, ec);
    if (ec) throw runtimeError(where, "cannot rename the joined video into place: {}", ec.message());
  }
  out.committed = true;
}

}  // namespace

JoinSummary joinParts(const std::vector<fs::path>& paths, const fs::path& output, const std::function<bool()>& stop) {
  const SourceLoc outLoc{"-o " + output.string()};
  if (paths.empty()) throw badInput(outLoc, "no parts to join");
  av_log_set_level(AV_LOG_ERROR);

  // Every part is read and checked before anything is written.
  std::vector<Part> parts;
  if (!inspectAllParts(paths, output, outLoc, stop, parts)) return {};
  const Part& ref = parts.front();
  const std::vector<const Part*> sorted = partsInClipOrder(parts);

  Output out;
  out.direct = av::isDevice(output);  // e.g. /dev/null: written in place, in the parts' container
  const AVOutputFormat* container = joinedContainer(out, output, ref, outLoc);
  out.writePath = output;
  if (!out.direct) {
    out.writePath.replace_filename(fmt::format(".{}.{}.tmp", output.filename().string(), ::getpid()));
    removeStaleTemporaries(output);  // a join that was killed (SIGKILL) left its temporary behind
    // A SIGINT/SIGTERM that ends the process removes it (core/temp_files.hpp).
    registerTemporary(out.writePath, output);
    out.registered = true;
  }
  const std::string url = "file:" + out.writePath.string();
  const SourceLoc where{output.string()};
  const AVStream* stream = createJoinMuxer(out, container, url, ref, where);
  CaptionCopier captions(out.format, ref, clipCaptions(sorted), av_inv_q(ref.frameRate), where);

  // The joined clip is tagged as the whole render: frames 0 … total − 1.
  ContainerTags whole = ref.tags;
  whole.firstFrame = 0;
  whole.lastFrame = whole.clipFrames - 1;
  writeJoinedHeader(out, whole, ref, url, where);
  if (!copyPartPackets(sorted, ref, out, stream, captions, where, stop))
    return {};  // ~Output removes the temporary file
  captions.writeUpTo(std::numeric_limits<std::int64_t>::max());
  finishJoinedFile(out, output, where);

  JoinSummary summary;
  summary.written = output;
  summary.frames = whole.clipFrames;
  summary.width = ref.codec->width;
  summary.height = ref.codec->height;
  summary.fpsNum = ref.frameRate.num;
  summary.fpsDen = ref.frameRate.den;
  summary.cues = captions.cues();
  return summary;
}

std::map<std::string, std::string> readContainerMetadata(const fs::path& path, const SourceLoc& where) {
  AVFormatContext* raw = nullptr;
  const std::string url = "file:" + path.string();
  if (const int ret = avformat_open_input(&raw, url.c_str(), nullptr, nullptr); ret < 0)
    throw badInput(where, "'{}' is not an image, figure or video rollspin can read: {}", path.string(),
                   av::errorText(ret));
  const Input input(raw);
  return metadataOf(*input);
}

}  // namespace rollspin::media
