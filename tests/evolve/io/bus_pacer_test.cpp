// BusPacer: when each message may go out, from the two token buckets.
#include "evolve/io/bus_pacer.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace robozoo {
namespace {

BusPacing messages_only(double per_second, double burst) {
  BusPacing p;
  p.bytes_per_second = 0;
  p.messages_per_second = per_second;
  p.burst_messages = burst;
  return p;
}

TEST(BusPacer, OneMessageAtATimeIsSpacedByTheInterval) {
  // 100 messages/s, one at a time: messages ready together go 10,000 us apart.
  BusPacer pacer(messages_only(100, 1));
  EXPECT_EQ(pacer.schedule(1'000'000, 10), 1'000'000);
  EXPECT_EQ(pacer.schedule(1'000'000, 10), 1'010'000);
  EXPECT_EQ(pacer.schedule(1'000'001, 10), 1'020'000);
  // Ready after its turn: at once.
  EXPECT_EQ(pacer.schedule(1'050'000, 10), 1'050'000);
  // Ready 4,000 us after that: waits the 6,000 us left.
  EXPECT_EQ(pacer.schedule(1'054'000, 10), 1'060'000);
}

TEST(BusPacer, ABurstGoesAtOnceThenTheRate) {
  // 200 messages/s after a burst of 3: three at once, then 5,000 us apart.
  BusPacer pacer(messages_only(200, 3));
  for (int i = 0; i < 3; ++i) EXPECT_EQ(pacer.schedule(0, 1), 0) << i;
  EXPECT_EQ(pacer.schedule(0, 1), 5'000);
  EXPECT_EQ(pacer.schedule(0, 1), 10'000);
  // After 15,000 us idle (3 tokens), a burst of 3 again.
  for (int i = 0; i < 3; ++i) EXPECT_EQ(pacer.schedule(25'000, 1), 25'000) << i;
  EXPECT_EQ(pacer.schedule(25'000, 1), 30'000);
}

TEST(BusPacer, BytesPaceLargeMessages) {
  // 1,000 bytes/s after a 500-byte burst, no message limit: 500 bytes at once,
  // then each 250-byte message 250 ms after the one before.
  BusPacing p;
  p.bytes_per_second = 1000;
  p.burst_bytes = 500;
  p.messages_per_second = 0;
  BusPacer pacer(p);
  EXPECT_EQ(pacer.schedule(0, 250), 0);
  EXPECT_EQ(pacer.schedule(0, 250), 0);
  EXPECT_EQ(pacer.schedule(0, 250), 250'000);
  EXPECT_EQ(pacer.schedule(0, 250), 500'000);
  // A 1,500-byte message waits for the full bucket (500 bytes) and delays the
  // next one by the 1,000 bytes beyond it: 1 s + 250 ms.
  EXPECT_EQ(pacer.schedule(0, 1500), 1'000'000);
  EXPECT_EQ(pacer.schedule(0, 250), 2'250'000);
}

TEST(BusPacer, TheSlowerBucketDecides) {
  // 100 messages/s and 1,000 bytes/s with a 100-byte burst: small messages go
  // 10 ms apart (the message limit), 50-byte ones 50 ms apart (the byte limit).
  BusPacing p;
  p.bytes_per_second = 1000;
  p.burst_bytes = 100;
  p.messages_per_second = 100;
  p.burst_messages = 1;
  BusPacer pacer(p);
  EXPECT_EQ(pacer.schedule(0, 1), 0);
  EXPECT_EQ(pacer.schedule(0, 1), 10'000);
  EXPECT_EQ(pacer.schedule(0, 50), 20'000);  // 99 bytes + 10 ms x 1,000 bytes/s, capped at 100: 50 left
  EXPECT_EQ(pacer.schedule(0, 50), 30'000);  // 50 + 10 = 60 at 30,000 us: 10 left
  EXPECT_EQ(pacer.schedule(0, 50), 70'000);  // 10 + 10 = 20 at 40,000 us: the 30 bytes more take 30 ms
}

TEST(BusPacer, UnpacedIsReadyTimeAndNeverGoesBack) {
  BusPacer pacer(messages_only(0, 1));
  EXPECT_EQ(pacer.schedule(500, 1'000'000), 500);
  EXPECT_EQ(pacer.schedule(700, 1), 700);
  EXPECT_EQ(pacer.schedule(600, 1), 700);  // never before the message scheduled before it
}

TEST(BusPacer, NotBeforeHoldsBackTheNextMessage) {
  // A resumed run whose log's last stamp is ahead of the clock: its messages
  // follow that stamp, then the usual 10,000 us apart.
  BusPacer pacer(messages_only(100, 1));
  pacer.not_before(5'000'000);
  EXPECT_EQ(pacer.schedule(1'000'000, 1), 5'000'000);
  EXPECT_EQ(pacer.schedule(1'000'000, 1), 5'010'000);
  pacer.not_before(4'000'000);  // earlier than what is booked: no effect
  EXPECT_EQ(pacer.schedule(1'000'000, 1), 5'020'000);
}

TEST(BusPacer, RefusesBadParameters) {
  EXPECT_THROW(BusPacer(messages_only(-1, 1)), std::invalid_argument);
  EXPECT_THROW(BusPacer(messages_only(100, 0.5)), std::invalid_argument);
  BusPacing p;
  p.bytes_per_second = std::numeric_limits<double>::infinity();
  EXPECT_THROW(BusPacer{p}, std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
