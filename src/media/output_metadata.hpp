// OutputMetadata — what an output says about how it was made, beside its
// pixels: the resolved scene text, the job that drew it (still, figure or
// clip and its own flags), the rollspin version and a one-sentence
// description (alt text). Each still format carries it its own way, written
// into the encoded bytes before they are committed and read back by
// readOutputMetadata:
//   PNG   iTXt chunks rollspin:scene, rollspin:job, Description, Software (before IEND)
//   JPEG  COM segments "KEY\0VALUE" after the JFIF header (long values split over several)
//   GIF   comment extensions "KEY\0VALUE" before the trailer
//   SVG   <title>, <desc> and <metadata> with rollspin: elements after the <svg> tag
//   PDF   an incremental update: a new Info dictionary (Title, Subject = the
//         description, Creator, Producer, Keywords, RollspinScene, RollspinJob)
//         and an XMP metadata stream in a new Catalog
// Video containers carry the same four as tags (container_tags.hpp). The
// bytes are the caller's: nothing here touches a file but readOutputMetadata.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace rollspin::media {

struct OutputMetadata {
  std::string title;        // a short name: render.title, else the scene's name
  std::string scene;        // the resolved scene (TOML)
  std::string job;          // the job record (jobs/remembered_job.hpp)
  std::string description;  // one sentence: the alt text
  std::string software;     // "rollspin 0.1.0 (git …)"
};

// The keys as PNG and the container tags name them.
inline constexpr std::string_view kSceneKey = "rollspin:scene";
inline constexpr std::string_view kJobKey = "rollspin:job";
inline constexpr std::string_view kDescriptionKey = "Description";
inline constexpr std::string_view kSoftwareKey = "Software";

// The encoded file with the metadata added; `png` etc. are complete files as
// an encoder wrote them. Throws Runtime when the bytes are not such a file.
[[nodiscard]] std::string withPngMetadata(std::string_view png, const OutputMetadata& m);
[[nodiscard]] std::string withJpegMetadata(std::string_view jpeg, const OutputMetadata& m);
[[nodiscard]] std::string withGifMetadata(std::string_view gif, const OutputMetadata& m);
[[nodiscard]] std::string withSvgMetadata(std::string_view svg, const OutputMetadata& m);
[[nodiscard]] std::string withPdfMetadata(std::string_view pdf, const OutputMetadata& m);

// The file formats readOutputMetadata knows by their first bytes.
enum class MetadataCarrier { Png, Jpeg, Gif, Svg, Pdf, Other };
[[nodiscard]] MetadataCarrier carrierOf(std::string_view bytes);

// The metadata of a still, figure or GIF file (by its bytes, not its name).
// BadInput naming `file` and what is missing: an unreadable file, one of
// another kind (Other: the caller tries the video containers), a rollspin
// key that is absent, truncated or corrupt (a bad CRC), or none at all.
[[nodiscard]] OutputMetadata parseOutputMetadata(std::string_view bytes, const std::string& file);

// Text as XML character data and back (&amp; &lt; &gt; &quot;; &apos; read
// too): the SVG's elements and the PDF's XMP packet.
[[nodiscard]] std::string xmlEscaped(std::string_view text);
[[nodiscard]] std::string xmlUnescaped(std::string_view text);

// parseOutputMetadata's PDF reader (output_metadata_pdf.cpp): the last Info
// dictionary's RollspinScene and RollspinJob, the XMP packet's texts.
[[nodiscard]] OutputMetadata parsePdfMetadata(std::string_view bytes, const std::string& file);

// SOURCE_DATE_EPOCH (seconds since 1970, UTC) when it is set and valid, else
// nullopt: the reproducible-builds convention for a fixed creation time.
[[nodiscard]] std::optional<long long> sourceDateEpoch();

}  // namespace rollspin::media
