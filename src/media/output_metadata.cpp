#include "media/output_metadata.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <map>
#include <vector>

#include "core/checksum.hpp"

namespace rollspin::media {

namespace {

using Fields = std::vector<std::pair<std::string_view, const std::string*>>;

// The four values under their keys, in the order every format writes them.
Fields fieldsOf(const OutputMetadata& m) {
  return {{kSceneKey, &m.scene}, {kJobKey, &m.job}, {kDescriptionKey, &m.description}, {kSoftwareKey, &m.software}};
}

void putBigEndian(std::string& out, std::uint32_t v, int bytes) {
  for (int k = bytes - 1; k >= 0; --k) out += static_cast<char>((v >> (8 * k)) & 0xFFU);
}

std::uint32_t bigEndian(std::string_view bytes, std::size_t at, int count) {
  std::uint32_t v = 0;
  for (int k = 0; k < count; ++k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
  return v;
}

[[noreturn]] void notRollspins(const std::string& file, std::string_view what) {
  throw badInput(SourceLoc{file},
                 "'{}' carries no rollspin metadata: {} (was it written by rollspin render, "
                 "without --no-metadata?)",
                 file, what);
}

// The values found under each key (a piece of a split value appended).
using Found = std::map<std::string, std::string, std::less<>>;

// The struct from what was found: every key must be there (the others may be
// empty); none at all is "not rollspin's", some is "incomplete".
OutputMetadata metadataFrom(Found found, const std::string& file, std::string_view where) {
  OutputMetadata m;
  bool any = false;
  for (const auto& [key, value] : fieldsOf(m)) any = any || found.contains(key);
  if (!any) notRollspins(file, fmt::format("no {} at all", where));
  const auto take = [&](std::string_view key) {
    const auto it = found.find(key);
    if (it == found.end())
      throw badInput(SourceLoc{file}, "'{}': the {} '{}' is missing (its metadata is incomplete)", file, where, key);
    return std::move(it->second);
  };
  m.scene = take(kSceneKey);
  m.job = take(kJobKey);
  m.description = take(kDescriptionKey);
  m.software = take(kSoftwareKey);
  return m;
}

}  // namespace

// PNG: iTXt = keyword, 0, compression flag 0, method 0, language "", 0,
// translated keyword "", 0, UTF-8 text; length, type, data, CRC of type + data.
std::string withPngMetadata(std::string_view png, const OutputMetadata& m) {
  constexpr std::size_t kIendSize = 12;
  if (png.size() < 8 + kIendSize || png.substr(png.size() - 8, 4) != "IEND")
    throw runtimeError(SourceLoc{"PNG encoder"}, "the encoded PNG does not end in IEND");
  std::string out(png.substr(0, png.size() - kIendSize));
  for (const auto& [key, value] : fieldsOf(m)) {
    std::string chunk = "iTXt";
    chunk.append(key).append(std::string_view("\0\0\0\0\0", 5)).append(*value);
    putBigEndian(out, static_cast<std::uint32_t>(chunk.size() - 4), 4);
    out += chunk;
    putBigEndian(out, crc32(chunk), 4);
  }
  out.append(png.substr(png.size() - kIendSize));
  return out;
}

namespace {

OutputMetadata parsePng(std::string_view bytes, const std::string& file) {
  Found found;
  std::size_t pos = 8;
  bool ended = false;
  while (pos + 12 <= bytes.size()) {
    const std::uint32_t length = bigEndian(bytes, pos, 4);
    const std::string_view type = bytes.substr(pos + 4, 4);
    if (length > bytes.size() - pos - 12)
      throw badInput(SourceLoc{file}, "'{}' is truncated: its '{}' chunk runs past the end", file, type);
    const std::string_view chunk = bytes.substr(pos + 4, 4 + length);
    if (crc32(chunk) != bigEndian(bytes, pos + 8 + length, 4))
      throw badInput(SourceLoc{file}, "'{}': its '{}' chunk is corrupt (bad CRC)", file, type);
    if (type == "iTXt") {
      const std::string_view data = chunk.substr(4);
      const std::size_t keyEnd = data.find('\0');
      // keyword, 0, flag, method, language, 0, translated keyword, 0, text
      const std::size_t lang = data.find('\0', keyEnd + 3), translated = data.find('\0', lang + 1);
      if (keyEnd != std::string_view::npos && translated != std::string_view::npos && data[keyEnd + 1] == 0) {
        found[std::string(data.substr(0, keyEnd))] = data.substr(translated + 1);
      }
    }
    pos += 12 + length;
    if (type == "IEND") ended = true;
    if (ended) break;
  }
  if (!ended) throw badInput(SourceLoc{file}, "'{}' is truncated: no IEND chunk", file);
  return metadataFrom(std::move(found), file, "PNG iTXt chunk");
}

// JPEG and GIF comments: "KEY\0VALUE", a long value over several comments
// of the same key, in order.
std::vector<std::string> keyedPieces(const OutputMetadata& m, std::size_t maxPiece) {
  std::vector<std::string> pieces;
  for (const auto& [key, value] : fieldsOf(m)) {
    std::size_t at = 0;
    do {
      pieces.push_back(std::string(key) + '\0' + value->substr(at, maxPiece - key.size() - 1));
      at += maxPiece - key.size() - 1;
    } while (at < value->size());
  }
  return pieces;
}

void addKeyedPiece(Found& found, std::string_view piece) {
  const std::size_t zero = piece.find('\0');
  if (zero == std::string_view::npos) return;  // someone else's comment
  found[std::string(piece.substr(0, zero))].append(piece.substr(zero + 1));
}

}  // namespace

std::string withJpegMetadata(std::string_view jpeg, const OutputMetadata& m) {
  if (jpeg.size() < 4 || bigEndian(jpeg, 0, 2) != 0xFFD8U)
    throw runtimeError(SourceLoc{"JPEG encoder"}, "the encoded JPEG does not start with SOI");
  // After SOI and the JFIF APP0 segment, which must come first.
  std::size_t insertAt = 2;
  if (bigEndian(jpeg, 2, 2) == 0xFFE0U) insertAt = 4 + bigEndian(jpeg, 4, 2);
  std::string out(jpeg.substr(0, insertAt));
  for (const std::string& piece : keyedPieces(m, 65533)) {
    out += "\xFF\xFE";
    putBigEndian(out, static_cast<std::uint32_t>(piece.size() + 2), 2);
    out += piece;
  }
  out.append(jpeg.substr(insertAt));
  return out;
}

namespace {

OutputMetadata parseJpeg(std::string_view bytes, const std::string& file) {
  Found found;
  std::size_t pos = 2;
  // The header segments up to the first scan: comments come before it.
  while (pos + 4 <= bytes.size() && static_cast<unsigned char>(bytes[pos]) == 0xFF) {
    const std::uint32_t marker = bigEndian(bytes, pos, 2), length = bigEndian(bytes, pos + 2, 2);
    if (length < 2 || pos + 2 + length > bytes.size())
      throw badInput(SourceLoc{file}, "'{}' is truncated: a segment runs past the end", file);
    if (marker == 0xFFFEU) addKeyedPiece(found, bytes.substr(pos + 4, length - 2));
    if (marker == 0xFFDAU) break;
    pos += 2 + length;
  }
  if (bytes.size() < 2 || bigEndian(bytes, bytes.size() - 2, 2) != 0xFFD9U)
    throw badInput(SourceLoc{file}, "'{}' is truncated: no end-of-image marker", file);
  return metadataFrom(std::move(found), file, "JPEG comment");
}

}  // namespace

// GIF: a comment extension (0x21 0xFE) per piece, its text in sub-blocks of
// at most 255 bytes, then a zero block; before the trailer (0x3B).
std::string withGifMetadata(std::string_view gif, const OutputMetadata& m) {
  if (gif.substr(0, 3) != "GIF" || gif.empty() || gif.back() != 0x3B)
    throw runtimeError(SourceLoc{"GIF encoder"}, "the encoded GIF does not end with its trailer");
  std::string out(gif.substr(0, gif.size() - 1));
  for (const std::string& piece : keyedPieces(m, 1 << 20)) {
    out += "\x21\xFE";
    for (std::size_t at = 0; at < piece.size(); at += 255) {
      const std::string_view block = std::string_view(piece).substr(at, 255);
      out += static_cast<char>(block.size());
      out += block;
    }
    out += '\0';
  }
  out += '\x3B';
  return out;
}

namespace {

// The comment extensions of a GIF, found by walking its blocks (an image's
// LZW data cannot be searched for 0x21 0xFE safely).
OutputMetadata parseGif(std::string_view bytes, const std::string& file) {
  const auto truncated = [&] { throw badInput(SourceLoc{file}, "'{}' is truncated: a block runs past the end", file); };
  if (bytes.size() < 13) truncated();
  const auto at = [&](std::size_t k) { return k < bytes.size() ? static_cast<unsigned char>(bytes[k]) : 0U; };
  const auto colourTable = [&](unsigned flags) { return (flags & 0x80U) ? 3U * (2U << (flags & 7U)) : 0U; };
  std::size_t pos = 13 + colourTable(at(10));
  // Sub-blocks from `pos`: returns their concatenation and moves past the zero block.
  const auto subBlocks = [&](std::size_t& p) {
    std::string data;
    while (p < bytes.size() && at(p) != 0) {
      if (p + 1 + at(p) > bytes.size()) truncated();
      data.append(bytes.substr(p + 1, at(p)));
      p += 1 + at(p);
    }
    if (p >= bytes.size()) truncated();
    ++p;
    return data;
  };
  Found found;
  while (true) {
    if (pos >= bytes.size()) truncated();
    if (at(pos) == 0x3B) break;
    if (at(pos) == 0x21) {
      const unsigned label = at(pos + 1);
      pos += 2;
      const std::string data = subBlocks(pos);
      if (label == 0xFE) addKeyedPiece(found, data);
    } else if (at(pos) == 0x2C) {  // image descriptor, local colour table, LZW size, data
      pos += 10 + colourTable(at(pos + 9)) + 1;
      subBlocks(pos);
    } else {
      throw badInput(SourceLoc{file}, "'{}' is not a well-formed GIF (block 0x{:02x} at byte {})", file, at(pos), pos);
    }
  }
  return metadataFrom(std::move(found), file, "GIF comment");
}

// <rollspin:scene>…</rollspin:scene> and the like: the rollspin elements.
std::string rollspinElements(const OutputMetadata& m) {
  return fmt::format(
      "<rollspin:scene>{}</rollspin:scene><rollspin:job>{}</rollspin:job>"
      "<rollspin:software>{}</rollspin:software>",
      xmlEscaped(m.scene), xmlEscaped(m.job), xmlEscaped(m.software));
}

// The text of the first <tag>…</tag> in `xml`, unescaped; nullopt when absent.
std::optional<std::string> elementText(std::string_view xml, std::string_view tag) {
  const std::string open = fmt::format("<{}>", tag), close = fmt::format("</{}>", tag);
  const std::size_t start = xml.find(open);
  if (start == std::string_view::npos) return std::nullopt;
  const std::size_t end = xml.find(close, start);
  if (end == std::string_view::npos) return std::nullopt;
  return xmlUnescaped(xml.substr(start + open.size(), end - start - open.size()));
}

constexpr std::string_view kNamespace = "urn:rollspin:metadata";

}  // namespace

std::string xmlEscaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string xmlUnescaped(std::string_view text) {
  static const std::array<std::pair<std::string_view, char>, 5> entities{
      {{"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}}};
  std::string out;
  for (std::size_t k = 0; k < text.size(); ++k) {
    bool replaced = false;
    for (const auto& [entity, c] : entities)
      if (text.substr(k, entity.size()) == entity) {
        out += c;
        k += entity.size() - 1;
        replaced = true;
        break;
      }
    if (!replaced) out += text[k];
  }
  return out;
}

std::string withSvgMetadata(std::string_view svg, const OutputMetadata& m) {
  const std::size_t open = svg.find("<svg");
  const std::size_t end = open == std::string_view::npos ? open : svg.find('>', open);
  if (end == std::string_view::npos) throw runtimeError(SourceLoc{"SVG writer"}, "the SVG has no <svg> element");
  return fmt::format(
      "{}\n<title>{}</title>\n<desc>{}</desc>\n<metadata><rollspin:metadata xmlns:rollspin=\"{}\">{}"
      "</rollspin:metadata></metadata>{}",
      svg.substr(0, end + 1), xmlEscaped(m.title), xmlEscaped(m.description), kNamespace, rollspinElements(m),
      svg.substr(end + 1));
}

namespace {

OutputMetadata parseSvg(std::string_view bytes, const std::string& file) {
  if (bytes.find("</svg>") == std::string_view::npos)
    throw badInput(SourceLoc{file}, "'{}' is truncated: no </svg> end tag", file);
  const std::size_t metadataEnd = bytes.find("</metadata>");
  const std::string_view head = bytes.substr(0, metadataEnd);
  Found found;
  for (const auto& [key, tag] : {std::pair{kSceneKey, "rollspin:scene"}, std::pair{kJobKey, "rollspin:job"},
                                 std::pair{kDescriptionKey, "desc"}, std::pair{kSoftwareKey, "rollspin:software"}})
    if (auto text = elementText(head, tag)) found[std::string(key)] = std::move(*text);
  // A <desc> alone is someone else's SVG, not an incomplete one of rollspin's.
  if (!found.contains(kSceneKey) && found.size() <= 1) found.clear();
  OutputMetadata m = metadataFrom(std::move(found), file, "SVG metadata element");
  if (auto title = elementText(head, "title")) m.title = *title;
  return m;
}

}  // namespace

MetadataCarrier carrierOf(std::string_view bytes) {
  if (bytes.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8)) return MetadataCarrier::Png;
  if (bytes.size() >= 2 && bigEndian(bytes, 0, 2) == 0xFFD8U) return MetadataCarrier::Jpeg;
  if (bytes.substr(0, 3) == "GIF") return MetadataCarrier::Gif;
  if (bytes.substr(0, 5) == "%PDF-") return MetadataCarrier::Pdf;
  const std::string_view head = bytes.substr(0, 512);
  if (head.find("<svg") != std::string_view::npos || head.find("<?xml") != std::string_view::npos)
    return MetadataCarrier::Svg;
  return MetadataCarrier::Other;
}

OutputMetadata parseOutputMetadata(std::string_view bytes, const std::string& file) {
  switch (carrierOf(bytes)) {
    case MetadataCarrier::Png: return parsePng(bytes, file);
    case MetadataCarrier::Jpeg: return parseJpeg(bytes, file);
    case MetadataCarrier::Gif: return parseGif(bytes, file);
    case MetadataCarrier::Svg: return parseSvg(bytes, file);
    case MetadataCarrier::Pdf: return parsePdfMetadata(bytes, file);
    case MetadataCarrier::Other: break;
  }
  notRollspins(file, "it is not a PNG, JPEG, GIF, SVG or PDF file");
}

std::optional<long long> sourceDateEpoch() {
  const char* text = std::getenv("SOURCE_DATE_EPOCH");
  if (text == nullptr || *text == '\0') return std::nullopt;
  long long value = 0;
  const std::string_view s(text);
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || ptr != s.data() + s.size() || value < 0) return std::nullopt;
  return value;
}

}  // namespace rollspin::media
