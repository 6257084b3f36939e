// core/text.hpp: ASCII lower case, the edit distance (with adjacent swaps)
// and the nearest name that the "did you mean" messages offer.
#include "core/text.hpp"

#include <gtest/gtest.h>

namespace rollspin {
namespace {

TEST(Text, LowercaseTouchesAsciiLettersOnly) {
  EXPECT_EQ(asciiLowercase("MP4.Mov_GIF-3"), "mp4.mov_gif-3");
  EXPECT_EQ(asciiLowercase("\xC3\x89t\xC3\xA9"), "\xC3\x89t\xC3\xA9");  // UTF-8 bytes pass unchanged
  EXPECT_EQ(asciiLowercase(""), "");
}

TEST(Text, EditDistanceCountsInsertionsDeletionsSubstitutionsAndSwaps) {
  EXPECT_EQ(editDistance("torus", "torus"), 0u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("abc", ""), 3u);
  EXPECT_EQ(editDistance("sphere", "spere"), 1u);   // a deletion
  EXPECT_EQ(editDistance("plane", "planes"), 1u);   // an insertion
  EXPECT_EQ(editDistance("saddle", "saddla"), 1u);  // a substitution
  EXPECT_EQ(editDistance("cirlce", "circle"), 1u);  // an adjacent swap is one edit
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(editDistance("abc", "cba"), editDistance("cba", "abc"));
}

TEST(Text, NearestNameIsOfferedOnlyForATypo) {
  const std::vector<std::string> kinds{"plane", "sphere", "cylinder", "torus", "paraboloid", "saddle", "height"};
  EXPECT_EQ(nearestName("spehre", kinds), "sphere");
  EXPECT_EQ(nearestName("toru", kinds), "torus");
  EXPECT_EQ(nearestName("cilinder", kinds), "cylinder");
  EXPECT_EQ(nearestName("sphere", kinds), "") << "a name spelled right is no typo";
  EXPECT_EQ(nearestName("banana", kinds), "") << "too far from every name";
  EXPECT_EQ(nearestName("x", kinds), "") << "one letter is no typo of a word";
  EXPECT_EQ(nearestName("tor", {"torus", "top"}), "top") << "the nearest wins";
  EXPECT_EQ(nearestName("torus", {}), "");
}

}  // namespace
}  // namespace rollspin
