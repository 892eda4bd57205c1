#include "render/video/frame_queue.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace robozoo::render {
namespace {

Image numbered(int k) { return Image(2, 2, Rgb{static_cast<uint8_t>(k), 0, 0}); }

TEST(FrameQueue, HandsOverEveryFrameInOrderAndReusesStorage) {
  FrameQueue queue(3);
  std::vector<int> seen;
  std::thread consumer([&] {
    Image f;
    while (queue.pop(f)) {
      seen.push_back(f.at(0, 0).r);
      queue.recycle(std::move(f));
    }
  });
  for (int k = 0; k < 200; ++k) ASSERT_TRUE(queue.push(numbered(k)));
  queue.close();
  consumer.join();
  ASSERT_EQ(seen.size(), 200u);
  for (int k = 0; k < 200; ++k) EXPECT_EQ(seen[k], k);
}

TEST(FrameQueue, RecycledFramesComeBackAsSpares) {
  FrameQueue queue(2);
  EXPECT_TRUE(queue.spare().empty());
  ASSERT_TRUE(queue.push(numbered(5)));
  Image f;
  ASSERT_TRUE(queue.pop(f));
  queue.recycle(std::move(f));
  const Image again = queue.spare();
  EXPECT_EQ(again.width(), 2);
  EXPECT_TRUE(queue.spare().empty());
}

TEST(FrameQueue, ProducerWaitsAtCapacity) {
  FrameQueue queue(2);
  ASSERT_TRUE(queue.push(numbered(0)));
  ASSERT_TRUE(queue.push(numbered(1)));
  std::atomic<bool> third{false};
  std::thread producer([&] {
    queue.push(numbered(2));
    third = true;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_FALSE(third.load()) << "a third frame went in while two were queued";
  Image f;
  ASSERT_TRUE(queue.pop(f));
  producer.join();
  EXPECT_TRUE(third.load());
}

TEST(FrameQueue, AbortReleasesBothSides) {
  FrameQueue queue(1);
  ASSERT_TRUE(queue.push(numbered(0)));
  std::thread producer([&] { EXPECT_FALSE(queue.push(numbered(1))); });  // blocked: full
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  queue.abort();
  producer.join();
  Image f;
  EXPECT_FALSE(queue.pop(f));  // aborted: queued frames are dropped
  EXPECT_TRUE(queue.aborted());
}

TEST(FrameQueue, ClosedQueueDrainsThenStops) {
  FrameQueue queue(4);
  ASSERT_TRUE(queue.push(numbered(7)));
  queue.close();
  Image f;
  ASSERT_TRUE(queue.pop(f));
  EXPECT_EQ(f.at(0, 0).r, 7);
  EXPECT_FALSE(queue.pop(f));
  EXPECT_THROW(queue.push(numbered(8)), std::logic_error);
  EXPECT_THROW(FrameQueue(0), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo::render
