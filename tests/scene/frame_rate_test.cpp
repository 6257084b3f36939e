// scene/frame_rate.hpp: a frame rate as an exact, reduced rational that fits
// the encoder's 32-bit time base: integers, NTSC decimals (N·1000/1001),
// other decimals of at most three places, and "num/den" text.
#include "scene/frame_rate.hpp"

#include <gtest/gtest.h>

#include <climits>

namespace rollspin::scene {
namespace {

TEST(FrameRate, IntegersAndNtscDecimalsAreExact) {
  EXPECT_EQ(frameRateFromDecimal(30.0), (FrameRate{30, 1}));
  EXPECT_EQ(frameRateFromDecimal(29.97), (FrameRate{30000, 1001}));
  EXPECT_EQ(frameRateFromDecimal(23.976), (FrameRate{24000, 1001}));
  EXPECT_EQ(frameRateFromDecimal(23.98), (FrameRate{24000, 1001})) << "two places name the same rate";
  EXPECT_EQ(frameRateFromDecimal(59.94), (FrameRate{60000, 1001}));
  EXPECT_EQ(frameRateFromDecimal(119.88), (FrameRate{120000, 1001}));
}

TEST(FrameRate, OtherDecimalsOfThreePlacesAreReduced) {
  EXPECT_EQ(frameRateFromDecimal(12.5), (FrameRate{25, 2}));
  EXPECT_EQ(frameRateFromDecimal(7.125), (FrameRate{57, 8}));
  EXPECT_EQ(frameRateFromDecimal(0.5), (FrameRate{1, 2}));
  EXPECT_EQ(frameRateFromDecimal(12.3456), std::nullopt) << "four places";
}

TEST(FrameRate, NoRateForNothingNegativeOrTooLarge) {
  EXPECT_EQ(frameRateFromDecimal(0.0), std::nullopt);
  EXPECT_EQ(frameRateFromDecimal(-30.0), std::nullopt);
  EXPECT_EQ(frameRateFromDecimal(std::numeric_limits<double>::quiet_NaN()), std::nullopt);
  EXPECT_EQ(frameRateFromDecimal(std::numeric_limits<double>::infinity()), std::nullopt);
  EXPECT_EQ(frameRateFromDecimal(2e6), std::nullopt);
}

TEST(FrameRate, TextIsARatioOrADecimal) {
  EXPECT_EQ(frameRateFromText("30000/1001"), (FrameRate{30000, 1001}));
  EXPECT_EQ(frameRateFromText("60/2"), (FrameRate{30, 1})) << "reduced";
  EXPECT_EQ(frameRateFromText("29.97"), (FrameRate{30000, 1001}));
  EXPECT_EQ(frameRateFromText("24"), (FrameRate{24, 1}));
  for (const char* bad :
       {"", "/", "30/", "/1001", "30/0", "0/1", "-30/1", "30 /1", "3e1/1", "abc", "30fps", "4294967296/1"})
    EXPECT_EQ(frameRateFromText(bad), std::nullopt) << bad;
  EXPECT_EQ(frameRateFromText(std::to_string(INT_MAX) + "/1"), (FrameRate{INT_MAX, 1}));
}

TEST(FrameRate, PrintsBackAsItReads) {
  const FrameRate ntsc{30000, 1001};
  EXPECT_EQ(ntsc.text(), "30000/1001");
  EXPECT_EQ(ntsc.describe(), "30000/1001 (29.97)");
  EXPECT_NEAR(ntsc.value(), 29.97002997, 1e-8);
  EXPECT_EQ((FrameRate{25, 1}).text(), "25");
  EXPECT_EQ((FrameRate{25, 1}).describe(), "25");
  EXPECT_EQ(frameRateFromText(ntsc.text()), ntsc);
}

}  // namespace
}  // namespace rollspin::scene
