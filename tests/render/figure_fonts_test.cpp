// render/figure_fonts.hpp: a figure's label text split into runs, each in the first face that has its
// characters (the family asked for, else DejaVu Sans), the faces' size metric, and fontconfig's silent
// substitution told apart from a real match. Needs the fonts install-deps.sh installs (fonts-dejavu-core,
// fonts-lmodern); no GL.
#include "render/figure_fonts.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "render/vector_figure.hpp"

namespace rollspin::render {
namespace figure_fonts_test {

// The code points of UTF-8 text, decoded here (not with the code under test's helper).
std::u32string codePoints(const std::string& utf8) {
  std::u32string out;
  for (std::size_t i = 0; i < utf8.size();) {
    const auto byte = static_cast<unsigned char>(utf8[i]);
    const int length = byte < 0x80 ? 1 : byte < 0xE0 ? 2 : byte < 0xF0 ? 3 : 4;
    char32_t c = length == 1 ? byte : byte & (0x7F >> length);
    for (int k = 1; k < length; ++k) c = (c << 6) | (static_cast<unsigned char>(utf8[i + k]) & 0x3F);
    out += c;
    i += std::size_t(length);
  }
  return out;
}

// One code point as UTF-8.
std::string encodeOne(char32_t c) {
  std::string out;
  if (c < 0x80) return std::string(1, static_cast<char>(c));
  const int length = c < 0x800 ? 2 : c < 0x10000 ? 3 : 4;
  static constexpr unsigned char kLead[] = {0, 0, 0xC0, 0xE0, 0xF0};
  out += static_cast<char>(kLead[length] | (c >> (6 * (length - 1))));
  for (int k = length - 2; k >= 0; --k) out += static_cast<char>(0x80 | ((c >> (6 * k)) & 0x3F));
  return out;
}

// Whether fontconfig's own match for the family has the character.
bool familyHas(const std::string& family, char32_t c) {
  FcPattern* match = matchFont(family, false);
  FcCharSet* charset = nullptr;
  const bool has = match != nullptr && FcPatternGetCharSet(match, FC_CHARSET, 0, &charset) == FcResultMatch &&
                   FcCharSetHasChar(charset, c);
  if (match != nullptr) FcPatternDestroy(match);
  return has;
}

std::string joined(const std::vector<FigureFonts::Run>& runs) {
  std::string out;
  for (const auto& r : runs) out += r.utf8;
  return out;
}

}  // namespace figure_fonts_test

using figure_fonts_test::codePoints;
using figure_fonts_test::familyHas;
using figure_fonts_test::joined;

// Latin Modern Roman has no ⟨ ⟩ (the reason for the fallback): those and only those go to DejaVu Sans, the
// runs keep the text's bytes and order (1- to 4-byte characters), and two runs side by side never share a face.
TEST(FigureFonts, ACharacterTheFamilyLacksIsDrawnInDejaVuSansAndEverythingElseInTheFamily) {
  const std::string family = "Latin Modern Roman";
  ASSERT_TRUE(familyHas(family, U'a')) << "fonts-lmodern is not installed";
  ASSERT_FALSE(familyHas(family, U'⟩')) << "this Latin Modern has ⟩: the test needs a character it lacks";
  ASSERT_TRUE(familyHas("DejaVu Sans", U'⟩'));
  const std::string text = "spin ⟨ψ|σ⟩ = é 𝜓!";
  FigureFonts fonts(family);
  const auto runs = fonts.runs(text, false);
  EXPECT_EQ(joined(runs), text);
  const FigureFonts::Face* primary = &fonts.face(false, false);
  const FigureFonts::Face* fallback = &fonts.face(false, true);
  ASSERT_NE(primary, fallback);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    if (k > 0) EXPECT_NE(runs[k].face, runs[k - 1].face) << "runs " << k - 1 << " and " << k << " share a face";
    for (char32_t c : codePoints(runs[k].utf8)) {
      // A space stays in the family's face whatever the family's charset says (no run broken for it).
      const bool inFamily = c == U' ' || familyHas(family, c);
      EXPECT_EQ(runs[k].face, inFamily ? primary : fallback) << "U+" << std::hex << std::uint32_t(c);
    }
  }
  // The runs, worked out here from fontconfig's answers character by character: "spin " in the family,
  // then the brackets (and whatever else it lacks) apart.
  std::vector<std::pair<bool, std::string>> expected;  // (in the family, text)
  for (const char32_t c : codePoints(text)) {
    const bool inFamily = c == U' ' || familyHas(family, c);
    if (expected.empty() || expected.back().first != inFamily) expected.emplace_back(inFamily, "");
    expected.back().second += figure_fonts_test::encodeOne(c);
  }
  ASSERT_EQ(runs.size(), expected.size());
  for (std::size_t k = 0; k < runs.size(); ++k) {
    EXPECT_EQ(runs[k].utf8, expected[k].second) << "run " << k;
    EXPECT_EQ(runs[k].face, expected[k].first ? primary : fallback) << "run " << k;
  }
  EXPECT_EQ(runs.front().utf8, "spin ");
  EXPECT_EQ(runs[1].face, fallback) << "⟨ is Latin Modern's gap";
}

// A family with every character gives one run; bold text gets the bold face, made once and kept.
TEST(FigureFonts, AFamilyWithEveryCharacterGivesOneRunInItsFaceAtTheWeightAsked) {
  FigureFonts fonts("DejaVu Sans");
  const auto regular = fonts.runs("⟨ψ|σ⟩ = 1", false);
  ASSERT_EQ(regular.size(), 1U);
  EXPECT_EQ(regular[0].face, &fonts.face(false, false));
  const auto bold = fonts.runs("⟨ψ|σ⟩ = 1", true);
  ASSERT_EQ(bold.size(), 1U);
  EXPECT_EQ(bold[0].face, &fonts.face(true, false));
  EXPECT_NE(bold[0].face, regular[0].face);
  int weight = 0;
  ASSERT_EQ(FcPatternGetInteger(bold[0].face->pattern, FC_WEIGHT, 0, &weight), FcResultMatch);
  EXPECT_GE(weight, FC_WEIGHT_BOLD);
  EXPECT_TRUE(fonts.runs("", false).empty());
}

// The size metric is the GL labels' (ascent + descent a font unit): DejaVu Sans's hhea table gives
// 1901 + 483 of 2048 units an em.
TEST(FigureFonts, HeightPerEmIsAscentPlusDescentOfTheFontsDesign) {
  EXPECT_NEAR(figureFontHeightPerEm("DejaVu Sans"), (1901.0 + 483.0) / 2048.0, 0.002);
  FigureFonts fonts("DejaVu Sans");
  EXPECT_DOUBLE_EQ(fonts.face(false, false).heightPerEm, figureFontHeightPerEm("DejaVu Sans"));
}

// fontconfig answers every family with some font: sameFamily tells a real match (any case) from a stand-in,
// and checkFigureFont refuses a family that is not installed, saying how to list the installed ones.
TEST(FigureFonts, AFamilyThatIsNotInstalledIsBadInputNotASilentStandIn) {
  FcPattern* dejavu = matchFont("dejavu sans", false);
  ASSERT_NE(dejavu, nullptr);
  EXPECT_TRUE(sameFamily(dejavu, "DejaVu Sans"));
  EXPECT_FALSE(sameFamily(dejavu, "Latin Modern Roman"));
  FcPatternDestroy(dejavu);
  const std::string missing = "No Such Family Rollspin";
  FcPattern* standIn = matchFont(missing, false);
  ASSERT_NE(standIn, nullptr) << "fontconfig substitutes some font";
  EXPECT_FALSE(sameFamily(standIn, missing));
  FcPatternDestroy(standIn);
  EXPECT_NO_THROW(checkFigureFont("DejaVu Sans", SourceLoc{"scene.toml"}));
  EXPECT_NO_THROW(checkFigureFont("Latin Modern Roman", SourceLoc{"scene.toml"}));
  try {
    checkFigureFont(missing, SourceLoc{"scene.toml", 3, 8});
    FAIL() << "no error for a family that is not installed";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    const std::string message = e.what();
    EXPECT_NE(message.find("figure.font"), std::string::npos) << message;
    EXPECT_NE(message.find("'" + missing + "'"), std::string::npos) << message;
    EXPECT_NE(message.find("fc-list : family"), std::string::npos) << message;
  }
}

}  // namespace rollspin::render
