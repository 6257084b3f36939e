// PDF metadata by an incremental update (PDF 1.7 §7.5.6): the file cairo
// wrote stays as it is, and a section appended after its %%EOF redefines the
// Catalog (adding /Metadata, an XMP stream) and points the trailer at a new
// Info dictionary. Readers take the last trailer; cairo 1.16 cannot set
// Subject-length texts, custom keys or XMP itself.
#include <fmt/format.h>

#include <charconv>
#include <ctime>
#include <optional>
#include <vector>

#include "media/output_metadata.hpp"

namespace rollspin::media {

namespace {

// A PDF text string as UTF-16BE with its byte order mark, in hex: any
// character, nothing to escape (§7.9.2.2).
std::string pdfTextString(std::string_view utf8) {
  std::string out = "<FEFF";
  for (std::size_t k = 0; k < utf8.size();) {
    const auto b = [&](std::size_t i) { return static_cast<unsigned char>(utf8[i]); };
    std::uint32_t c = b(k);
    int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
    if (extra > 0) c &= 0x3FU >> extra;
    for (int j = 1; j <= extra && k + j < utf8.size(); ++j) c = (c << 6) | (b(k + j) & 0x3FU);
    k += 1 + extra;
    if (c >= 0x10000) {
      c -= 0x10000;
      out += fmt::format("{:04X}{:04X}", 0xD800 + (c >> 10), 0xDC00 + (c & 0x3FF));
    } else {
      out += fmt::format("{:04X}", c);
    }
  }
  return out + ">";
}

// A byte string in hex (§7.3.4.3): the scene text as written, byte for byte.
std::string pdfHexBytes(std::string_view bytes) {
  std::string out = "<";
  for (const char c : bytes) out += fmt::format("{:02X}", static_cast<unsigned char>(c));
  return out + ">";
}

std::optional<std::string> fromHex(std::string_view hex) {
  std::string out;
  for (std::size_t k = 0; k + 1 < hex.size(); k += 2) {
    unsigned v = 0;
    const auto [ptr, ec] = std::from_chars(hex.data() + k, hex.data() + k + 2, v, 16);
    if (ec != std::errc() || ptr != hex.data() + k + 2) return std::nullopt;
    out += static_cast<char>(v);
  }
  return out;
}

// The integer after `key` in the last trailer (" /Size 8"), or -1.
long long trailerNumber(std::string_view trailer, std::string_view key) {
  const std::size_t at = trailer.find(key);
  if (at == std::string_view::npos) return -1;
  std::size_t p = at + key.size();
  while (p < trailer.size() && (trailer[p] == ' ' || trailer[p] == '\n' || trailer[p] == '\r')) ++p;
  long long v = -1;
  std::from_chars(trailer.data() + p, trailer.data() + trailer.size(), v);
  return v;
}

std::string creationDate() {
  const std::time_t t = sourceDateEpoch().value_or(static_cast<long long>(std::time(nullptr)));
  std::tm utc{};
  gmtime_r(&t, &utc);
  return fmt::format("D:{:04}{:02}{:02}{:02}{:02}{:02}Z", utc.tm_year + 1900, utc.tm_mon + 1, utc.tm_mday, utc.tm_hour,
                     utc.tm_min, utc.tm_sec);
}

constexpr std::string_view kAltOpen = "<rdf:Alt><rdf:li xml:lang=\"x-default\">", kAltClose = "</rdf:li></rdf:Alt>";

std::string xmpPacket(const OutputMetadata& m) {
  return fmt::format(
      "<?xpacket begin=\"\xEF\xBB\xBF\" id=\"W5M0MpCehiHzreSzNTczkc9d\"?>\n"
      "<x:xmpmeta xmlns:x=\"adobe:ns:meta/\"><rdf:RDF xmlns:rdf=\"http://www.w3.org/1999/02/22-rdf-syntax-ns#\">\n"
      "<rdf:Description rdf:about=\"\" xmlns:dc=\"http://purl.org/dc/elements/1.1/\" "
      "xmlns:xmp=\"http://ns.adobe.com/xap/1.0/\" xmlns:rollspin=\"urn:rollspin:metadata\">\n"
      "<dc:title>{0}{2}{1}</dc:title>\n<dc:description>{0}{3}{1}</dc:description>\n"
      "<xmp:CreatorTool>{4}</xmp:CreatorTool>\n<rollspin:scene>{5}</rollspin:scene>\n<rollspin:job>{6}</rollspin:job>\n"
      "</rdf:Description></rdf:RDF></x:xmpmeta>\n<?xpacket end=\"w\"?>",
      kAltOpen, kAltClose, xmlEscaped(m.title), xmlEscaped(m.description), xmlEscaped(m.software), xmlEscaped(m.scene),
      xmlEscaped(m.job));
}

// The text between the last `open` and the `close` after it, unescaped; "" when absent.
std::string lastBetween(std::string_view bytes, std::string_view open, std::string_view close) {
  const std::size_t at = bytes.rfind(open);
  if (at == std::string_view::npos) return {};
  const std::size_t end = bytes.find(close, at + open.size());
  if (end == std::string_view::npos) return {};
  return xmlUnescaped(bytes.substr(at + open.size(), end - at - open.size()));
}

// The Catalog object's dictionary body (between its outer << >>), from the
// object `root` as cairo wrote it.
std::string catalogBody(std::string_view pdf, long long root) {
  const std::string head = fmt::format("\n{} 0 obj\n", root);
  const std::size_t start = pdf.rfind(head);
  const std::size_t open = start == std::string_view::npos ? start : pdf.find("<<", start);
  const std::size_t end = open == std::string_view::npos ? open : pdf.find("endobj", open);
  const std::size_t close = end == std::string_view::npos ? end : pdf.rfind(">>", end);
  if (close == std::string_view::npos || close < open)
    throw runtimeError(SourceLoc{"PDF writer"}, "the Catalog (object {}) was not found", root);
  return std::string(pdf.substr(open + 2, close - open - 2));
}

}  // namespace

std::string withPdfMetadata(std::string_view pdf, const OutputMetadata& m) {
  const std::size_t trailerAt = pdf.rfind("trailer");
  const std::size_t startxrefAt = pdf.rfind("startxref");
  if (trailerAt == std::string_view::npos || startxrefAt == std::string_view::npos)
    throw runtimeError(SourceLoc{"PDF writer"}, "the PDF has no trailer");
  const std::string_view trailer = pdf.substr(trailerAt, startxrefAt - trailerAt);
  const long long size = trailerNumber(trailer, "/Size"), root = trailerNumber(trailer, "/Root");
  const long long previous = trailerNumber(pdf.substr(startxrefAt), "startxref");
  if (size <= 0 || root <= 0 || previous <= 0)
    throw runtimeError(SourceLoc{"PDF writer"}, "the PDF's trailer is not cairo's");
  std::string out(pdf);
  if (out.back() != '\n') out += '\n';
  const long long info = size, xmp = size + 1;
  std::vector<std::pair<long long, std::size_t>> offsets;  // object → byte offset
  offsets.emplace_back(root, out.size());
  out += fmt::format("{} 0 obj\n<<{}   /Metadata {} 0 R\n>>\nendobj\n", root, catalogBody(pdf, root), xmp);
  offsets.emplace_back(info, out.size());
  out += fmt::format(
      "{} 0 obj\n<< /Title {}\n   /Subject {}\n   /Creator {}\n   /Producer {}\n   /Keywords {}\n"
      "   /CreationDate ({})\n   /RollspinScene {}\n   /RollspinJob {}\n>>\nendobj\n",
      info, pdfTextString(m.title), pdfTextString(m.description), pdfTextString(m.software), pdfTextString(m.software),
      pdfTextString("rollspin, rolling sphere, spin-1/2, Bloch sphere"), creationDate(), pdfHexBytes(m.scene),
      pdfHexBytes(m.job));
  const std::string packet = xmpPacket(m);
  offsets.emplace_back(xmp, out.size());
  out += fmt::format("{} 0 obj\n<< /Type /Metadata /Subtype /XML /Length {} >>\nstream\n{}\nendstream\nendobj\n", xmp,
                     packet.size(), packet);
  const std::size_t xref = out.size();
  out += fmt::format("xref\n{} 1\n{:010} 00000 n \n{} 2\n{:010} 00000 n \n{:010} 00000 n \n", root, offsets[0].second,
                     info, offsets[1].second, offsets[2].second);
  out += fmt::format("trailer\n<< /Size {}\n   /Root {} 0 R\n   /Info {} 0 R\n   /Prev {}\n>>\nstartxref\n{}\n%%EOF\n",
                     size + 2, root, info, previous, xref);
  return out;
}

// The last Info dictionary's rollspin keys and Subject; what it lacks is
// named. A file that does not end in %%EOF is truncated.
OutputMetadata parsePdfMetadata(std::string_view bytes, const std::string& file) {
  const std::size_t eof = bytes.rfind("%%EOF");
  if (eof == std::string_view::npos || bytes.substr(eof).find_first_not_of("%EOF\r\n") != std::string_view::npos)
    throw badInput(SourceLoc{file}, "'{}' is truncated: it does not end in %%EOF", file);
  const auto hexValue = [&](std::string_view key) -> std::optional<std::string> {
    const std::size_t at = bytes.rfind(fmt::format("/{} <", key));
    if (at == std::string_view::npos) return std::nullopt;
    const std::size_t open = bytes.find('<', at), close = bytes.find('>', open);
    if (close == std::string_view::npos) return std::nullopt;
    return fromHex(bytes.substr(open + 1, close - open - 1));
  };
  const auto scene = hexValue("RollspinScene");
  if (!scene)
    throw badInput(SourceLoc{file},
                   "'{}' carries no rollspin metadata: its Info dictionary has no RollspinScene "
                   "(was it written by rollspin render, without --no-metadata?)",
                   file);
  const auto job = hexValue("RollspinJob");
  if (!job)
    throw badInput(SourceLoc{file}, "'{}': the PDF Info key 'RollspinJob' is missing (its metadata is incomplete)",
                   file);
  OutputMetadata m;
  m.scene = *scene;
  m.job = *job;
  // Info's texts are UTF-16BE: the XMP packet has the same in UTF-8.
  m.title = lastBetween(bytes, fmt::format("<dc:title>{}", kAltOpen), kAltClose);
  m.description = lastBetween(bytes, fmt::format("<dc:description>{}", kAltOpen), kAltClose);
  m.software = lastBetween(bytes, "<xmp:CreatorTool>", "</xmp:CreatorTool>");
  return m;
}

}  // namespace rollspin::media
