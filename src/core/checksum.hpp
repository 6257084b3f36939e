// CRC-32 (ISO-HDLC: PNG chunks, ZIP members, gzip): the reflected polynomial
// 0xEDB88320, initial and final value 0xFFFFFFFF (ISO 3309; PNG spec §5.5).
#pragma once

#include <cstdint>
#include <string_view>

namespace rollspin {

// The CRC-32 of `bytes`; `previous` continues a CRC over several pieces
// (crc32(b, crc32(a)) == crc32(a + b)).
[[nodiscard]] std::uint32_t crc32(std::string_view bytes, std::uint32_t previous = 0);

}  // namespace rollspin
