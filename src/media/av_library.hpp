// AvLibrary — FFmpeg's functions for the video sinks and `join`, resolved with
// dlopen on first use. libavcodec and libavfilter bring in about 140 shared
// libraries (every codec Debian builds in); loading them took 0.1 s of every
// start, `rollspin solve` included. Now only a command that writes or joins
// video loads them, and the others run without FFmpeg installed.
//
// Each function is an object of the same name in rollspin::media, so calls
// inside the namespace read as plain libav calls: `avcodec_open2(...)` finds
// this object before the global declaration. The first call loads the five
// libraries (the sonames the headers were built against) and resolves every
// function; a missing library throws Error naming it. Internal to media/.
#pragma once

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/frame.h>
#include <libavutil/hash.h>
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <cstddef>
#include <string>

// Every libav function media/ calls, by library; a call to one not listed
// here fails to link (the executable does not link libav*).
// clang-format off
#define ROLLSPIN_AV_FUNCTIONS(X)                                                                               \
  /* libavutil */                                                                                              \
  X(avutil_version) X(av_buffer_create) X(av_dict_free) X(av_dict_get) X(av_dict_set) X(av_frame_alloc) X(av_frame_free)         \
  X(av_frame_get_buffer) X(av_frame_make_writable) X(av_frame_unref) X(av_get_pix_fmt) X(av_hash_alloc)        \
  X(av_hash_final_hex) X(av_hash_freep) X(av_hash_init) X(av_hash_update) X(av_log_set_level) X(av_opt_find)   \
  X(av_opt_set) X(av_opt_set_int) X(av_opt_set_pixel_fmt) X(av_rescale_q) X(av_strdup) X(av_strerror)                       \
  /* libavcodec */                                                                                             \
  X(avcodec_version) X(av_new_packet) X(av_packet_alloc) X(av_packet_free) X(av_packet_rescale_ts) X(av_packet_unref) X(avcodec_alloc_context3) X(avcodec_encode_subtitle) \
  X(avcodec_find_encoder_by_name) X(avcodec_free_context) X(avcodec_get_name) X(avcodec_open2)                 \
  X(avcodec_parameters_alloc) X(avcodec_parameters_copy) X(avcodec_parameters_free)                            \
  X(avcodec_parameters_from_context) X(avcodec_receive_packet) X(avcodec_send_frame)                           \
  /* libavformat */                                                                                            \
  X(avformat_version) X(av_guess_format) X(av_interleaved_write_frame) X(av_read_frame) X(av_write_trailer)                        \
  X(avformat_alloc_output_context2) X(avformat_close_input) X(avformat_find_stream_info)                       \
  X(avformat_free_context) X(avformat_new_stream) X(avformat_open_input) X(avformat_write_header)               \
  X(avio_closep) X(avio_flush) X(avio_open)                                                                    \
  /* libavfilter */                                                                                            \
  X(av_buffersink_get_frame) X(av_buffersrc_add_frame) X(av_buffersrc_add_frame_flags) X(avfilter_get_by_name) \
  X(avfilter_graph_alloc) X(avfilter_graph_config) X(avfilter_graph_create_filter) X(avfilter_graph_free)      \
  X(avfilter_link) X(avfilter_version)                                                                        \
  /* libswscale */                                                                                             \
  X(sws_alloc_context) X(sws_freeContext) X(sws_getCoefficients) X(sws_init_context) X(sws_scale_frame)        \
  X(sws_setColorspaceDetails) X(swscale_version)
// clang-format on

namespace rollspin::media {

namespace av_library {

enum Index : std::size_t {
#define ROLLSPIN_AV_INDEX(name) name##_index,
  ROLLSPIN_AV_FUNCTIONS(ROLLSPIN_AV_INDEX)
#undef ROLLSPIN_AV_INDEX
      count
};

// The resolved address of function `index`; loads the libraries on the
// first call (thread-safe). Throws Error when a library or function is missing.
void* symbol(std::size_t index);

// ROLLSPIN_LIBAV_DIR names a folder to load the libraries from (another
// FFmpeg build of the same major versions); unset, the dynamic loader's
// search path serves. For messages: "DIR ($ROLLSPIN_LIBAV_DIR)", or "" when
// it is unset.
std::string customDirectoryNamed();

template <class Signature>
struct Function;

template <class Result, class... Args>
struct Function<Result(Args...)> {
  std::size_t index;
  Result operator()(Args... args) const { return reinterpret_cast<Result (*)(Args...)>(symbol(index))(args...); }
};

}  // namespace av_library

// A function type drops libav's av_warn_unused_result, which g++ notes.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wignored-attributes"
#define ROLLSPIN_AV_DECLARE(name) \
  inline constexpr av_library::Function<decltype(::name)> name{av_library::name##_index};
ROLLSPIN_AV_FUNCTIONS(ROLLSPIN_AV_DECLARE)
#undef ROLLSPIN_AV_DECLARE
#pragma GCC diagnostic pop

}  // namespace rollspin::media
