#pragma once
// A bounded queue of frames from the thread that draws them to the thread that
// encodes them, so the two overlap while neither runs ahead by more than
// `capacity` frames (memory stays bounded: 2.7 MB a 1280x720 frame). Frames
// handed back by the consumer are reused by the producer, so drawing and
// encoding allocate nothing once the pipeline is full.
#include <condition_variable>
#include <deque>
#include <mutex>
#include <vector>

#include "render/gl/image.hpp"

namespace robozoo::render {

class FrameQueue {
 public:
  /// Throws std::invalid_argument for a capacity below 1.
  explicit FrameQueue(int capacity);

  /// Producer: an image to draw into (a used one when there is one, else empty).
  Image spare();
  /// Producer: queues a frame, waiting while `capacity` frames are queued.
  /// False when the queue was aborted (the frame is dropped).
  bool push(Image frame);
  /// Producer: no more frames; the consumer drains the queue and stops.
  void close();

  /// Consumer: the next frame in order, waiting while none is queued. False
  /// once the queue is closed and drained, or aborted.
  bool pop(Image& frame);
  /// Consumer: returns a frame's storage for reuse.
  void recycle(Image frame);

  /// Either side: stop both at once (after a failure); queued frames are dropped.
  void abort();
  bool aborted() const;

 private:
  const size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Image> queue_;
  std::vector<Image> spares_;
  bool closed_ = false, aborted_ = false;
};

}  // namespace robozoo::render
