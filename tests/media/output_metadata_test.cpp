// What a still, figure or GIF carries (media/output_metadata.hpp): written
// into real encoder output (stb's PNG and JPEG) or a minimal file of each
// format, read back whole; a value past one JPEG comment's 65533 bytes;
// what a truncated file, a bad CRC and a missing key say.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "media/image_io.hpp"
#include "media/output_metadata.hpp"
#include "support/test_files.hpp"

namespace rollspin::media {
namespace {

OutputMetadata sample(std::size_t sceneSize = 0) {
  OutputMetadata m;
  m.title = "Lollipop & <friends>";
  m.scene = sceneSize ? std::string(sceneSize, 'x') : "[ball]\nradius = 1 # \"one\" & <b>\n";
  m.job = "render: still\nscene: lollipop\n";
  m.description = "A ball of radius 1 rolls once round a circle; beside it the spin on the Bloch sphere.";
  m.software = "rollspin 0.1.0";
  return m;
}

void expectSame(const OutputMetadata& a, const OutputMetadata& b) {
  EXPECT_EQ(a.scene, b.scene);
  EXPECT_EQ(a.job, b.job);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.software, b.software);
}

std::string encoded(bool jpeg, const OutputMetadata* m) {
  const auto dir = test::freshTempDir("output_metadata");
  Image image(5, 3);
  for (std::size_t k = 0; k < image.rgba.size(); ++k) image.rgba[k] = static_cast<std::uint8_t>(k * 17);
  const auto file = dir / (jpeg ? "a.jpg" : "a.png");
  if (jpeg) writeJpeg(file, image.view(), 90, m);
  else writePng(file, image.view(), PngChannels::Rgb, m);
  return test::readFile(file);
}

TEST(OutputMetadata, PngAndJpegRoundTripAndStillDecode) {
  for (const bool jpeg : {false, true}) {
    const OutputMetadata m = sample();
    const std::string bytes = encoded(jpeg, &m);
    expectSame(parseOutputMetadata(bytes, "a"), m);
    // The pixels are the same as without the metadata.
    EXPECT_EQ(decodeImage(bytes, "a", SourceLoc{"a"}).rgba,
              decodeImage(encoded(jpeg, nullptr), "b", SourceLoc{"b"}).rgba);
  }
}

TEST(OutputMetadata, ALongSceneSpansSeveralJpegComments) {
  const OutputMetadata m = sample(150000);
  expectSame(parseOutputMetadata(encoded(true, &m), "a.jpg"), m);
}

TEST(OutputMetadata, GifSvgAndPdfRoundTrip) {
  const OutputMetadata m = sample(600);  // over a GIF sub-block's 255 bytes
  // GIF89a, a 1x1 screen with a 2-colour table, one image, the trailer.
  const std::string gif(
      "GIF89a\x01\x00\x01\x00\x80\x00\x00\x00\x00\x00\xff\xff\xff"
      "\x2c\x00\x00\x00\x00\x01\x00\x01\x00\x00\x02\x02\x44\x01\x00\x3b",
      35);
  expectSame(parseOutputMetadata(withGifMetadata(gif, m), "a.gif"), m);
  const std::string svg = "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1\"><g/></svg>\n";
  const OutputMetadata fromSvg = parseOutputMetadata(withSvgMetadata(svg, m), "a.svg");
  expectSame(fromSvg, m);
  EXPECT_EQ(fromSvg.title, m.title);
  const std::string pdf =
      "%PDF-1.5\n1 0 obj\n<< /Type /Catalog\n   /Pages 2 0 R\n>>\nendobj\nxref\n0 2\n"
      "0000000000 65535 f \n0000000009 00000 n \ntrailer\n<< /Size 3\n   /Root 1 0 R\n>>\n"
      "startxref\n57\n%%EOF\n";
  const std::string withMetadata = withPdfMetadata(pdf, m);
  expectSame(parseOutputMetadata(withMetadata, "a.pdf"), m);
  EXPECT_NE(withMetadata.find("/Prev 57"), std::string::npos);
  EXPECT_NE(withMetadata.find("/Metadata 4 0 R"), std::string::npos);
}

// Exit 2 at the file, saying what is wrong.
std::string refusal(const std::string& bytes) {
  try {
    (void)parseOutputMetadata(bytes, "x.png");
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(e.message().find("x.png"), std::string::npos) << e.message();
    return e.message();
  }
  ADD_FAILURE() << "accepted";
  return {};
}

TEST(OutputMetadata, BrokenOrForeignFilesAreRefusedSayingWhy) {
  const OutputMetadata m = sample();
  const std::string png = encoded(false, &m);
  EXPECT_NE(refusal(png.substr(0, png.size() - 12)).find("no IEND"), std::string::npos);
  std::string corrupt = png;
  corrupt[png.find("[ball]")] ^= 1;
  EXPECT_NE(refusal(corrupt).find("bad CRC"), std::string::npos);
  EXPECT_NE(refusal(encoded(false, nullptr)).find("no rollspin metadata"), std::string::npos);
  OutputMetadata partial = m;
  const std::string jpeg = encoded(true, &partial);
  // A JPEG without its job comment: incomplete, naming the key.
  const std::size_t job = jpeg.find("rollspin:job");
  std::string withoutJob = jpeg;
  withoutJob.replace(job, 12, "rollspin:xyz");
  EXPECT_NE(refusal(withoutJob).find("'rollspin:job' is missing"), std::string::npos);
  EXPECT_NE(refusal("not an image").find("not a PNG, JPEG, GIF, SVG or PDF"), std::string::npos);
}

}  // namespace
}  // namespace rollspin::media
