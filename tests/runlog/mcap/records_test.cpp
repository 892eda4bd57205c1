#include "runlog/mcap/records.hpp"

#include <gtest/gtest.h>

namespace robozoo::mcap {
namespace {

TEST(Records, HeaderBytesByHand) {
  Bytes b;
  append(b, Header{"", "rz"});
  // opcode 1, length 10 (uint64 LE), profile "" (uint32 0), library "rz" (uint32 2 + 2 bytes)
  const Bytes want = {0x01, 10, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, 'r', 'z'};
  EXPECT_EQ(b, want);
}

TEST(Records, FooterBytesByHand) {
  Bytes b;
  append(b, Footer{0x0102, 0x0304, 0xA1B2C3D4u});
  const Bytes want = {0x02, 20,   0,    0,   0, 0, 0, 0, 0,  // opcode, length 20
                      0x02, 0x01, 0,    0,   0, 0, 0, 0,     // summary_start
                      0x04, 0x03, 0,    0,   0, 0, 0, 0,     // summary_offset_start
                      0xD4, 0xC3, 0xB2, 0xA1};               // summary_crc
  EXPECT_EQ(b, want);
  EXPECT_EQ(b.size(), kFooterRecordBytes);
}

TEST(Records, MessageBytesByHand) {
  Bytes b;
  append(b, Message{3, 7, 0x10, 0x20, "{}"});
  const Bytes want = {0x05, 24, 0, 0, 0, 0, 0, 0, 0,  // 2 + 4 + 8 + 8 + 2 content bytes
                      3,    0,  7, 0, 0, 0,           // channel id, sequence
                      0x10, 0,  0, 0, 0, 0, 0, 0,     // log time
                      0x20, 0,  0, 0, 0, 0, 0, 0,     // publish time
                      '{',  '}'};
  EXPECT_EQ(b, want);
}

TEST(Records, ChannelMetadataMapIsLengthPrefixedInBytes) {
  Bytes b;
  append(b, Channel{1, 2, "t", "json", {{"k", "v"}}});
  // content: id 2 + schema 2 + "t" 5 + "json" 8 + map (4 + "k" 5 + "v" 5) = 31
  ASSERT_EQ(b.size(), 9u + 31u);
  EXPECT_EQ(b[0], 0x04);
  EXPECT_EQ(b[1], 31);
  const size_t map_at = 9 + 2 + 2 + 5 + 8;
  EXPECT_EQ(b[map_at], 10);     // the map's entries take 10 bytes
  EXPECT_EQ(b[map_at + 4], 1);  // key length
  EXPECT_EQ(b[map_at + 8], 'k');
  EXPECT_EQ(b[map_at + 13], 'v');
}

TEST(Records, MessageIndexArrayHoldsPairs) {
  Bytes b;
  append(b, MessageIndex{5, {{100, 0}, {200, 31}}});
  // content: channel 2 + array prefix 4 + 2 * 16
  ASSERT_EQ(b.size(), 9u + 38u);
  EXPECT_EQ(b[0], 0x07);
  EXPECT_EQ(b[9], 5);
  EXPECT_EQ(b[11], 32);       // array bytes
  EXPECT_EQ(b[15], 100);      // first log time
  EXPECT_EQ(b[15 + 24], 31);  // second offset
}

TEST(Records, DataEndAndSummaryOffset) {
  Bytes b;
  append(b, DataEnd{0x01020304u});
  EXPECT_EQ(b, (Bytes{0x0F, 4, 0, 0, 0, 0, 0, 0, 0, 4, 3, 2, 1}));
  b.clear();
  append(b, SummaryOffset{Opcode::ChunkIndex, 9, 17});
  ASSERT_EQ(b.size(), 9u + 17u);
  EXPECT_EQ(b[9], 0x08);
  EXPECT_EQ(b[10], 9);
  EXPECT_EQ(b[18], 17);
}

}  // namespace
}  // namespace robozoo::mcap
