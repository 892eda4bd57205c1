#include "render/video/frame_queue.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace robozoo::render {

FrameQueue::FrameQueue(int capacity) : capacity_(capacity > 0 ? static_cast<size_t>(capacity) : 0) {
  if (capacity < 1)
    throw std::invalid_argument("frame queue capacity must be at least 1, got " + std::to_string(capacity));
}

Image FrameQueue::spare() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (spares_.empty()) return Image();
  Image image = std::move(spares_.back());
  spares_.pop_back();
  return image;
}

bool FrameQueue::push(Image frame) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return aborted_ || queue_.size() < capacity_; });
  if (aborted_) return false;
  if (closed_) throw std::logic_error("FrameQueue::push after close");
  queue_.push_back(std::move(frame));
  lock.unlock();
  changed_.notify_all();
  return true;
}

void FrameQueue::close() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

bool FrameQueue::pop(Image& frame) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return aborted_ || closed_ || !queue_.empty(); });
  if (aborted_ || queue_.empty()) return false;
  frame = std::move(queue_.front());
  queue_.pop_front();
  lock.unlock();
  changed_.notify_all();
  return true;
}

void FrameQueue::recycle(Image frame) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (spares_.size() < capacity_ + 1) spares_.push_back(std::move(frame));
}

void FrameQueue::abort() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    aborted_ = true;
    queue_.clear();
  }
  changed_.notify_all();
}

bool FrameQueue::aborted() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return aborted_;
}

}  // namespace robozoo::render
