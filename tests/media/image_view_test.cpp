// media/image_view: rows through a padded stride in either order, tight top-down copies and images, the cross-fade.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "media/image_view.hpp"

namespace rollspin::media {
namespace {

// `rows` stored rows of `width` pixels and `stride` bytes each, the padding
// bytes 0xEE; pixel byte c of the row that is y from the top is
// 16 y + 4 x + c + 1 whatever the storage order.
std::vector<std::uint8_t> paddedRows(int width, int rows, std::ptrdiff_t stride, RowOrder order) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(stride * rows), 0xEE);
  for (int y = 0; y < rows; ++y) {
    const int stored = order == RowOrder::TopDown ? y : rows - 1 - y;
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 4; ++c)
        bytes[stored * stride + 4 * x + c] = static_cast<std::uint8_t>(16 * y + 4 * x + c + 1);
  }
  return bytes;
}

TEST(ImageView, RowFromTopStepsByTheStrideInEitherRowOrder) {
  const std::vector<std::uint8_t> bytes(5 * 20, 0);
  const ImageView topDown{3, 5, 20, bytes.data(), RowOrder::TopDown};
  const ImageView bottomUp{3, 5, 20, bytes.data(), RowOrder::BottomUp};
  for (int y = 0; y < 5; ++y) {
    EXPECT_EQ(topDown.rowFromTop(y), bytes.data() + 20 * y) << y;
    EXPECT_EQ(bottomUp.rowFromTop(y), bytes.data() + 20 * (4 - y)) << y;
  }
}

// The copy is tight (width · 4 bytes a row, no padding) and top row first.
TEST(ImageView, CopyTopDownDropsThePaddingOfEitherRowOrder) {
  for (const RowOrder order : {RowOrder::TopDown, RowOrder::BottomUp}) {
    const std::vector<std::uint8_t> bytes = paddedRows(3, 4, 20, order);
    const Image copy = copyTopDown(ImageView{3, 4, 20, bytes.data(), order});
    ASSERT_EQ(copy.width, 3);
    ASSERT_EQ(copy.height, 4);
    ASSERT_EQ(copy.rgba.size(), 3u * 4u * 4u);
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 3; ++x)
        for (int c = 0; c < 4; ++c)
          EXPECT_EQ(copy.pixel(x, y)[c], 16 * y + 4 * x + c + 1) << x << "," << y << " c " << c;
  }
}

TEST(Image, IsZeroedTightAndTopDownWithRowMajorPixels) {
  Image img(5, 3);
  ASSERT_EQ(img.rgba.size(), 60u);
  for (const std::uint8_t b : img.rgba) EXPECT_EQ(b, 0);
  const ImageView v = img.view();
  EXPECT_EQ(v.width, 5);
  EXPECT_EQ(v.height, 3);
  EXPECT_EQ(v.stride, 20);
  EXPECT_EQ(v.rows, RowOrder::TopDown);
  EXPECT_EQ(v.rgba, img.rgba.data());
  for (int y = 0; y < 3; ++y) {
    EXPECT_EQ(v.rowFromTop(y), img.pixel(0, y)) << y;
    for (int x = 0; x < 5; ++x) EXPECT_EQ(img.pixel(x, y), img.rgba.data() + 4 * (5 * y + x)) << x << "," << y;
  }
  img.pixel(4, 2)[3] = 9;
  EXPECT_EQ(img.rgba.back(), 9);
  const Image empty;
  EXPECT_EQ(empty.view().width * empty.view().height, 0);
}

// One byte of `into` faded towards one byte of `from` at `weight`.
std::uint8_t fadedByte(std::uint8_t into, std::uint8_t from, double weight) {
  Image a(1, 1), b(1, 1);
  a.rgba[0] = into;
  b.rgba[0] = from;
  crossFade(a, b, weight);
  return a.rgba[0];
}

// At a weight of a whole number of 256ths every pair of bytes gives the
// blend weight · from + (1 − weight) · into rounded to nearest (halves up).
TEST(CrossFade, EveryPairOfBytesIsTheRoundedBlendAtWholeWeightsOf256ths) {
  for (const int k : {0, 1, 3, 64, 128, 192, 255, 256}) {
    const double weight = k / 256.0;
    Image into(256, 256), from(256, 256);
    for (int a = 0; a < 256; ++a)
      for (int b = 0; b < 256; ++b) {
        into.pixel(b, a)[0] = static_cast<std::uint8_t>(a);
        from.pixel(b, a)[0] = static_cast<std::uint8_t>(b);
      }
    crossFade(into, from, weight);
    for (int a = 0; a < 256; ++a)
      for (int b = 0; b < 256; ++b) {
        const long expected = std::lround(weight * b + (1.0 - weight) * a);  // exact: k · b is a whole number
        ASSERT_EQ(into.pixel(b, a)[0], expected) << "k " << k << " into " << a << " from " << b;
      }
  }
}

// Any other weight is within a level of the exact blend (the weight itself
// is rounded to 256ths); weights past 0 or 1 are clamped.
TEST(CrossFade, OtherWeightsAreWithinALevelAndWeightsOutsideZeroToOneAreClamped) {
  for (const double weight : {0.3, 1.0 / 3.0, 0.7, 0.999})
    for (int a = 0; a < 256; a += 5)
      for (int b = 0; b < 256; b += 3)
        ASSERT_LE(std::abs(fadedByte(static_cast<std::uint8_t>(a), static_cast<std::uint8_t>(b), weight) -
                           (weight * b + (1.0 - weight) * a)),
                  1.0)
            << "weight " << weight << " into " << a << " from " << b;
  EXPECT_EQ(fadedByte(40, 200, -0.5), 40);
  EXPECT_EQ(fadedByte(40, 200, 1.7), 200);
}

}  // namespace
}  // namespace rollspin::media
