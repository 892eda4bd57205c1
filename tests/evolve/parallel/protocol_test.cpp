#include "evolve/parallel/protocol.hpp"

#include <gtest/gtest.h>

#include <string>

namespace robozoo {
namespace {

Bytes bytes_of(const std::string& s) { return Bytes(s.begin(), s.end()); }

Bytes ramp(size_t n) {
  Bytes b(n);
  for (size_t i = 0; i < n; ++i) b[i] = static_cast<uint8_t>(i * 131u + 7u);
  return b;
}

TEST(Protocol, Crc32CheckValue) {
  // The standard check value of CRC-32/ISO-HDLC (zlib's crc32).
  const Bytes b = bytes_of("123456789");
  EXPECT_EQ(crc32(b.data(), b.size()), 0xCBF43926u);
  // Incremental use gives the same value.
  EXPECT_EQ(crc32(b.data() + 4, 5, crc32(b.data(), 4)), 0xCBF43926u);
  EXPECT_EQ(crc32(nullptr, 0), 0u);
}

TEST(Protocol, LayoutIsAsDocumented) {
  const Bytes f = encode_job(Job{0x0102030405060708ull, bytes_of("abc")});
  ASSERT_EQ(f.size(), kFrameHeaderBytes + 3 + kFrameTrailerBytes);
  EXPECT_EQ(std::string(f.begin(), f.begin() + 4), "RZWP");
  EXPECT_EQ(f[4], kProtocolVersion);
  EXPECT_EQ(f[5], static_cast<uint8_t>(FrameKind::Job));
  EXPECT_EQ(f[6], 0);
  EXPECT_EQ(f[7], 0);
  EXPECT_EQ(f[8], 0x08);  // little-endian index
  EXPECT_EQ(f[15], 0x01);
  EXPECT_EQ(f[16], 3);  // length
  EXPECT_EQ(f[17] | f[18] | f[19], 0);
  EXPECT_EQ(f[20], static_cast<uint8_t>(~3u & 0xFF));  // its complement
  EXPECT_EQ(f[23], 0xFF);
  EXPECT_EQ(std::string(f.begin() + 24, f.begin() + 27), "abc");
  const uint32_t crc = crc32(f.data(), 27);
  EXPECT_EQ(f[27] | (f[28] << 8) | (f[29] << 16) | (static_cast<uint32_t>(f[30]) << 24), crc);
}

TEST(Protocol, JobRoundTrip) {
  for (size_t n : {size_t{0}, size_t{1}, size_t{1000}, size_t{300000}}) {
    const Job job{123456789012345ull + n, ramp(n)};
    const Job back = job_from_frame(decode_message(encode_job(job)));
    EXPECT_EQ(back.index, job.index);
    EXPECT_EQ(back.payload, job.payload);
  }
}

TEST(Protocol, ResultAndFailureRoundTrip) {
  const Result ok{7, true, ramp(100), ""};
  const Result r = result_from_frame(decode_message(encode_result(ok)));
  EXPECT_EQ(r.index, 7u);
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.payload, ok.payload);

  const Result bad{9, false, {}, "genome has no output node"};
  const Result f = result_from_frame(decode_message(encode_result(bad)));
  EXPECT_EQ(f.index, 9u);
  EXPECT_FALSE(f.ok);
  EXPECT_TRUE(f.payload.empty());
  EXPECT_EQ(f.error, bad.error);
}

TEST(Protocol, ShutdownRoundTripAndKindChecks) {
  const Frame s = decode_message(encode_shutdown());
  EXPECT_EQ(s.kind, FrameKind::Shutdown);
  EXPECT_THROW(job_from_frame(s), ProtocolError);
  EXPECT_THROW(result_from_frame(s), ProtocolError);
  EXPECT_THROW(result_from_frame(decode_message(encode_job(Job{1, {}}))), ProtocolError);
  EXPECT_THROW(job_from_frame(decode_message(encode_result(Result{1, true, {}, ""}))), ProtocolError);
  EXPECT_THROW(encode_frame(Frame{FrameKind::Shutdown, 0, Bytes{1}}), std::invalid_argument);
  EXPECT_THROW(encode_frame(Frame{FrameKind::Shutdown, 5, {}}), std::invalid_argument);
  EXPECT_THROW(encode_frame(Frame{static_cast<FrameKind>(9), 0, {}}), std::invalid_argument);
}

TEST(Protocol, TruncatedFrameNeedsMoreOnAStreamAndFailsAsAMessage) {
  const Bytes f = encode_job(Job{3, ramp(50)});
  for (size_t n = 0; n < f.size(); ++n) {
    const DecodeStep step = decode_frame(f.data(), n);
    EXPECT_FALSE(step.frame.has_value()) << n;
    EXPECT_EQ(step.consumed, 0u);
    EXPECT_THROW(decode_message(Bytes(f.begin(), f.begin() + static_cast<std::ptrdiff_t>(n))), ProtocolError) << n;
  }
  const DecodeStep full = decode_frame(f.data(), f.size());
  ASSERT_TRUE(full.frame.has_value());
  EXPECT_EQ(full.consumed, f.size());
}

TEST(Protocol, TrailingBytesRejectedInAMessage) {
  Bytes f = encode_job(Job{3, ramp(5)});
  f.push_back(0);
  EXPECT_THROW(decode_message(f), ProtocolError);
}

TEST(Protocol, EverySingleBitFlipIsRejected) {
  const Bytes good = encode_result(Result{42, true, ramp(40), ""});
  for (size_t byte = 0; byte < good.size(); ++byte) {
    for (int bit = 0; bit < 8; ++bit) {
      Bytes bad = good;
      bad[byte] ^= static_cast<uint8_t>(1u << bit);
      EXPECT_THROW(decode_message(bad), ProtocolError) << "byte " << byte << " bit " << bit;
      // On a stream it is rejected too, never taken for a frame, at the latest when complete.
      bool rejected = false;
      try {
        rejected = !decode_frame(bad.data(), bad.size()).frame.has_value();
      } catch (const ProtocolError&) {
        rejected = true;
      }
      EXPECT_TRUE(rejected) << "byte " << byte << " bit " << bit;
    }
  }
}

TEST(Protocol, BadHeaderFailsBeforeItsBodyArrives) {
  Bytes f = encode_job(Job{1, ramp(1000)});
  Bytes lie = f;
  lie[16] ^= 0x10;  // length no longer matches its complement
  EXPECT_THROW(decode_frame(lie.data(), kFrameHeaderBytes), ProtocolError);
  Bytes magic = f;
  magic[1] = 'X';
  EXPECT_THROW(decode_frame(magic.data(), 2), ProtocolError);  // even from two bytes
  Bytes version = f;
  version[4] = kProtocolVersion + 1;
  EXPECT_THROW(decode_frame(version.data(), kFrameHeaderBytes), ProtocolError);
  Bytes kind = f;
  kind[5] = 0;
  EXPECT_THROW(decode_frame(kind.data(), kFrameHeaderBytes), ProtocolError);
  Bytes reserved = f;
  reserved[7] = 1;
  EXPECT_THROW(decode_frame(reserved.data(), kFrameHeaderBytes), ProtocolError);
}

TEST(Protocol, ConsistentButOversizedLengthIsRejected) {
  // A header claiming 2 GiB (length and complement consistent, CRC never reached):
  // the reader's cap refuses it from the header alone, without allocating.
  Bytes f = encode_job(Job{1, {}});
  const uint32_t n = 0x80000000u;
  for (int i = 0; i < 4; ++i) {
    f[16 + i] = static_cast<uint8_t>(n >> (8 * i));
    f[20 + i] = static_cast<uint8_t>(~n >> (8 * i));
  }
  EXPECT_THROW(decode_frame(f.data(), kFrameHeaderBytes), ProtocolError);
  const Bytes small = encode_job(Job{1, ramp(100)});
  EXPECT_THROW(decode_frame(small.data(), small.size(), 99), ProtocolError);
  EXPECT_NO_THROW(decode_frame(small.data(), small.size(), 100));
}

TEST(Protocol, ShutdownWithABodyIsRejected) {
  // Build a Shutdown frame by hand with a body and a valid CRC.
  Bytes f = encode_job(Job{0, bytes_of("x")});
  f[5] = static_cast<uint8_t>(FrameKind::Shutdown);
  const uint32_t crc = crc32(f.data(), kFrameHeaderBytes + 1);
  for (int i = 0; i < 4; ++i) f[kFrameHeaderBytes + 1 + i] = static_cast<uint8_t>(crc >> (8 * i));
  EXPECT_THROW(decode_message(f), ProtocolError);
}

TEST(Protocol, FrameReaderCutsAStreamFedInPieces) {
  Bytes stream;
  std::vector<Job> sent;
  for (uint64_t i = 0; i < 20; ++i) {
    sent.push_back(Job{i, ramp(i * 37)});
    const Bytes f = encode_job(sent.back());
    stream.insert(stream.end(), f.begin(), f.end());
  }
  for (size_t piece : {size_t{1}, size_t{7}, size_t{4096}, stream.size()}) {
    FrameReader reader;
    std::vector<Job> got;
    for (size_t at = 0; at < stream.size(); at += piece) {
      reader.feed(stream.data() + at, std::min(piece, stream.size() - at));
      while (auto f = reader.next()) got.push_back(job_from_frame(std::move(*f)));
    }
    EXPECT_EQ(reader.buffered(), 0u);
    ASSERT_EQ(got.size(), sent.size()) << "piece " << piece;
    for (size_t i = 0; i < sent.size(); ++i) {
      EXPECT_EQ(got[i].index, sent[i].index);
      EXPECT_EQ(got[i].payload, sent[i].payload);
    }
  }
}

TEST(Protocol, FrameReaderStaysFailedAfterABadFrame) {
  Bytes good = encode_job(Job{1, ramp(10)});
  Bytes bad = good;
  bad[30] ^= 1;  // body byte: CRC mismatch
  FrameReader reader;
  reader.feed(good.data(), good.size());
  reader.feed(bad.data(), bad.size());
  reader.feed(good.data(), good.size());
  EXPECT_TRUE(reader.next().has_value());
  EXPECT_THROW(reader.next(), ProtocolError);
  EXPECT_THROW(reader.next(), ProtocolError);  // no resynchronisation
  reader.clear();
  reader.feed(good.data(), good.size());
  EXPECT_TRUE(reader.next().has_value());
}

}  // namespace
}  // namespace robozoo
