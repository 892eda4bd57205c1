#include "runlog/mcap/compression.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace robozoo::mcap {
namespace {

Bytes sample() {
  Bytes b;
  for (int i = 0; i < 5000; ++i) b.push_back(static_cast<uint8_t>((i * 7) % 13));
  return b;
}

TEST(Compression, NamesAsTheSpecSpellsThem) {
  EXPECT_EQ(compression_name(Compression::Zstd), "zstd");
  EXPECT_EQ(compression_name(Compression::Lz4), "lz4");
  EXPECT_EQ(compression_name(Compression::None), "");
  EXPECT_EQ(parse_compression("lz4"), Compression::Lz4);
  EXPECT_THROW(parse_compression("gzip"), std::invalid_argument);
}

TEST(Compression, RoundTripsAndShrinksRepetitiveData) {
  const Bytes data = sample();
  for (Compression c : {Compression::Zstd, Compression::Lz4, Compression::None}) {
    const Bytes packed = compress(c, data);
    if (c != Compression::None) {
      EXPECT_LT(packed.size(), data.size() / 4) << compression_name(c);
    }
    EXPECT_EQ(decompress(c, packed, data.size()), data) << compression_name(c);
  }
}

TEST(Compression, ZstdFrameMagic) {
  const Bytes packed = compress(Compression::Zstd, sample());
  ASSERT_GE(packed.size(), 4u);
  EXPECT_EQ(packed[0], 0x28);  // zstd frame magic 0xFD2FB528, little-endian
  EXPECT_EQ(packed[3], 0xFD);
  const Bytes lz4 = compress(Compression::Lz4, sample());
  EXPECT_EQ(lz4[0], 0x04);  // lz4 frame magic 0x184D2204
  EXPECT_EQ(lz4[3], 0x18);
}

TEST(Compression, DamagedInputIsAnError) {
  Bytes packed = compress(Compression::Zstd, sample());
  packed[0] ^= 0xFF;
  EXPECT_THROW(decompress(Compression::Zstd, packed, sample().size()), std::runtime_error);
  EXPECT_THROW(decompress(Compression::Lz4, Bytes{1, 2, 3}, 10), std::runtime_error);
}

}  // namespace
}  // namespace robozoo::mcap
