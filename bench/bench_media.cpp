// RGBA → yuv420p at 1920×1080 (ROLLSPIN_BENCH_SIZE for another size), CPU
// per frame: the video writer's converter (media/yuv420_converter) when a
// frame changes in a few blocks as a fixed-camera clip's do, when it changes
// everywhere (a moving camera), and swscale's bilinear BT.709 conversion of
// the whole frame on one thread, which it replaced for 8-bit 4:2:0. The
// "Time" column is wall time: with threads it falls below the CPU time.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

#include "bench_size.hpp"
#include "media/image_view.hpp"
#include "media/yuv420_converter.hpp"

extern "C" {
#include <libavutil/pixfmt.h>
#include <libswscale/swscale.h>
}

namespace {

using rollspin::media::Image;

// yuv420p halves both sizes: they must be even.
std::pair<int, int> benchSize() {
  const rollspin::bench::FrameSize& size = rollspin::bench::benchFrameSize("bench_media");
  if (size.width % 2 != 0 || size.height % 2 != 0) {
    std::fprintf(stderr, "bench_media: ROLLSPIN_BENCH_SIZE must be even in both sizes for yuv420p\n");
    std::exit(2);
  }
  return {size.width, size.height};
}

Image noise(int width, int height, unsigned seed) {
  Image image(width, height);
  std::mt19937 random(seed);
  for (auto& byte : image.rgba) byte = static_cast<std::uint8_t>(random());
  return image;
}

struct Planes {
  std::vector<std::uint8_t> y, u, v;
  int width;
  explicit Planes(int w, int h)
      : y(std::size_t(w) * h), u(std::size_t(w) * h / 4), v(std::size_t(w) * h / 4), width(w) {}
  rollspin::media::Yuv420Planes view() {
    return {y.data(), u.data(), v.data(), nullptr, width, width / 2, width / 2, 0};
  }
};

// Args: the percentage of the frame's rows, in one band, that change from
// frame to frame (9: about the 8.6 % of pixels a fixed-camera lollipop
// frame redraws; 100: every pixel), and the converter's threads.
void BM_Yuv420Converter(benchmark::State& state) {
  const auto [width, height] = benchSize();
  Image frames[2] = {noise(width, height, 1), noise(width, height, 1)};
  const int bandRows = static_cast<int>(height * state.range(0) / 100) & ~1;
  // The second frame differs from the first in a band of rows across the middle.
  const int firstRow = (height - bandRows) / 2 & ~1;
  for (int y = firstRow; y < firstRow + bandRows; ++y)
    for (int x = 0; x < width; ++x) frames[1].pixel(x, y)[0] ^= 0x55;
  Planes planes(width, height);
  rollspin::media::Yuv420Converter converter(width, height, static_cast<int>(state.range(1)));
  converter.convert(frames[0].view(), planes.view());
  long long k = 1;
  for (auto _ : state) benchmark::DoNotOptimize(converter.convert(frames[k++ % 2].view(), planes.view()));
}
BENCHMARK(BM_Yuv420Converter)
    ->Args({0, 1})
    ->Args({9, 1})
    ->Args({100, 1})
    ->Args({100, 2})
    ->Args({100, 4})
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);

// swscale, as the writer configured it before (bilinear, BT.709 into
// limited range), one thread, the whole frame every time.
void BM_SwscaleWholeFrame(benchmark::State& state) {
  const auto [width, height] = benchSize();
  const Image frame = noise(width, height, 2);
  SwsContext* sws = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P, SWS_BILINEAR,
                                   nullptr, nullptr, nullptr);
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  Planes planes(width, height);
  std::uint8_t* dst[4] = {planes.y.data(), planes.u.data(), planes.v.data(), nullptr};
  const int dstStride[4] = {width, width / 2, width / 2, 0};
  const std::uint8_t* src[4] = {frame.rgba.data(), nullptr, nullptr, nullptr};
  const int srcStride[4] = {width * 4, 0, 0, 0};
  for (auto _ : state) benchmark::DoNotOptimize(sws_scale(sws, src, srcStride, 0, height, dst, dstStride));
  sws_freeContext(sws);
}
BENCHMARK(BM_SwscaleWholeFrame)->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond);

}  // namespace
