// ContainerTags: the metadata a rendered clip carries for `rollspin join`
// round-trips through the key/value form, malformed or missing keys are
// named, and the scene hash is SHA-256 (FIPS 180-2 test vectors).
#include <gtest/gtest.h>

#include <map>

#include "media/container_tags.hpp"

namespace rollspin::media {
namespace {

ContainerTags sample() {
  ContainerTags t;
  t.sceneSha256 = sha256Hex("[ball]\nradius = 1\n");
  t.version = "0.1.0";
  t.encoderSettings = "libx264 preset=medium crf=18 yuv420p bt709 160x90 30/1 fps";
  t.firstFrame = 10;
  t.lastFrame = 19;
  t.clipFrames = 30;
  return t;
}

std::map<std::string, std::string> asMap(const ContainerTags& t) {
  std::map<std::string, std::string> m;
  for (const auto& [k, v] : containerMetadata(t)) m[k] = v;
  return m;
}

TEST(ContainerTags, RoundTripThroughMetadata) {
  const ContainerTags t = sample();
  const auto m = asMap(t);
  EXPECT_EQ(m.at("rollspin_frames"), "10-19");
  EXPECT_EQ(m.at("rollspin_clip_frames"), "30");
  const auto back = parseContainerTags(m);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(*back, t);
  EXPECT_EQ(back->frameCount(), 10);
}

TEST(ContainerTags, MissingOrMalformedKeysAreNamed) {
  auto m = asMap(sample());
  m.erase("rollspin_version");
  std::string why;
  EXPECT_FALSE(parseContainerTags(m, &why).has_value());
  EXPECT_NE(why.find("rollspin_version"), std::string::npos) << why;

  for (const char* frames : {"19-10", "10", "a-b", "-1-5", "10-19x"}) {
    auto bad = asMap(sample());
    bad["rollspin_frames"] = frames;
    EXPECT_FALSE(parseContainerTags(bad, &why).has_value()) << frames;
    EXPECT_NE(why.find("rollspin_frames"), std::string::npos) << why;
  }
  auto shortClip = asMap(sample());
  shortClip["rollspin_clip_frames"] = "19";  // the range ends at frame 19: the clip needs 20
  EXPECT_FALSE(parseContainerTags(shortClip, &why).has_value());
  EXPECT_NE(why.find("rollspin_clip_frames"), std::string::npos) << why;
}

TEST(ContainerTags, Sha256MatchesTheStandardVectors) {
  EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

}  // namespace
}  // namespace rollspin::media
