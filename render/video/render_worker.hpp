#pragma once
// A thread that draws: it owns the OpenGL context (OSMesa contexts belong to
// one thread) and works through a queue of jobs, so that whoever feeds it
// (live mode's LCM loop) never waits for drawing or encoding.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "render/scene/robot_card.hpp"
#include "render/video/video.hpp"
#include "render/zoo/zoo_sheet.hpp"

namespace robozoo::render {

struct WorkerCounts {
  int64_t pictures = 0;    ///< PNGs written (count)
  int64_t videos = 0;      ///< videos written (count)
  int64_t failures = 0;    ///< jobs that failed (count)
  int64_t superseded = 0;  ///< pictures replaced by a newer one before being drawn (count)
};

class RenderWorker {
 public:
  /// `report` receives one line per finished or failed job (called from the
  /// worker thread; it must be thread-safe).
  RenderWorker(ZooOptions picture, VideoOptions video, std::function<void(const std::string&)> report);
  /// Finishes the queued jobs, then stops.
  ~RenderWorker();
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  /// Draws `card` with its caption to `path` (PNG). A picture still waiting
  /// is replaced: only the newest champion matters.
  void picture(RobotCard card, std::string path);
  /// Renders a behaviour video to `path`.
  void video(VideoSubject subject, std::string path);
  /// Blocks until the queue is empty and the worker idle.
  void wait_idle();
  WorkerCounts counts() const;

 private:
  struct Job {
    bool is_video = false;
    RobotCard card;
    VideoSubject subject;
    std::string path;
  };
  void run();

  ZooOptions picture_options_;
  VideoOptions video_options_;
  std::function<void(const std::string&)> report_;
  mutable std::mutex mutex_;
  std::condition_variable wake_, idle_;
  std::deque<Job> queue_;
  bool busy_ = false, stopping_ = false;
  WorkerCounts counts_;
  std::thread thread_;
};

}  // namespace robozoo::render
