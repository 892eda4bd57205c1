#include "evolve/io/crc32.hpp"

#include <gtest/gtest.h>

#include <string>

namespace robozoo {
namespace {

TEST(Crc32, CheckValueOfTheStandardString) {
  // The catalogue check value of CRC-32/ISO-HDLC (zlib's crc32, MCAP's and the worker protocol's).
  const std::string s = "123456789";
  EXPECT_EQ(crc32(s.data(), s.size(), 0), 0xCBF43926u);
}

TEST(Crc32, EmptyInputKeepsTheCrc) {
  EXPECT_EQ(crc32("", 0, 0), 0u);
  EXPECT_EQ(crc32("", 0, 0x1234u), 0x1234u);
  // zlib answers 0 for a null buffer whatever the CRC so far; an empty extension keeps it.
  EXPECT_EQ(crc32(nullptr, 0, 0x1234u), 0x1234u);
}

TEST(Crc32, SingleByteByHand) {
  // CRC-32 of the one byte 'a' (0x61): 0xE8B7BE43.
  EXPECT_EQ(crc32("a", 1, 0), 0xE8B7BE43u);
}

TEST(Crc32, IncrementalEqualsWhole) {
  const std::string s = "the quick brown fox jumps over the lazy dog";
  const uint32_t whole = crc32(s.data(), s.size(), 0);
  for (size_t cut = 0; cut <= s.size(); cut += 7) {
    const uint32_t first = crc32(s.data(), cut, 0);
    EXPECT_EQ(crc32(s.data() + cut, s.size() - cut, first), whole) << cut;
  }
}

}  // namespace
}  // namespace robozoo
