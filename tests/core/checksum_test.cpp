// CRC-32 against the check value of its catalogue entry (CRC-32/ISO-HDLC:
// the CRC of the ASCII digits "123456789" is 0xCBF43926) and the chaining
// that PNG chunks and ZIP members rely on.
#include <gtest/gtest.h>

#include "core/checksum.hpp"

namespace rollspin {
namespace {

TEST(Crc32, MatchesTheCatalogueCheckValue) {
  EXPECT_EQ(crc32("123456789"), 0xCBF43926U);
  EXPECT_EQ(crc32(""), 0U);
}

TEST(Crc32, ContinuesOverPieces) {
  EXPECT_EQ(crc32("56789", crc32("1234")), crc32("123456789"));
  EXPECT_NE(crc32("123456788"), crc32("123456789"));
}

}  // namespace
}  // namespace rollspin
