#include "render/video/render_worker.hpp"

#include <cstdio>
#include <exception>
#include <memory>

#include "render/gl/png_io.hpp"
#include "render/scene/stage.hpp"
#include "render/gl/text.hpp"

namespace robozoo::render {

RenderWorker::RenderWorker(ZooOptions picture, VideoOptions video, std::function<void(const std::string&)> report)
    : picture_options_(std::move(picture)), video_options_(std::move(video)), report_(std::move(report)) {
  validate(picture_options_);
  validate(video_options_);
  thread_ = std::thread([this] { run(); });
}

RenderWorker::~RenderWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void RenderWorker::picture(RobotCard card, std::string path) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = queue_.begin(); it != queue_.end();)
      if (!it->is_video && it->path == path) {
        it = queue_.erase(it);
        ++counts_.superseded;
      } else {
        ++it;
      }
    Job j;
    j.card = std::move(card);
    j.path = std::move(path);
    queue_.push_back(std::move(j));
  }
  wake_.notify_all();
}

void RenderWorker::video(VideoSubject subject, std::string path) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    Job j;
    j.is_video = true;
    j.subject = std::move(subject);
    j.path = std::move(path);
    queue_.push_back(std::move(j));
  }
  wake_.notify_all();
}

void RenderWorker::wait_idle() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [this] { return queue_.empty() && !busy_; });
}

WorkerCounts RenderWorker::counts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return counts_;
}

void RenderWorker::run() {
  std::unique_ptr<Stage> stage;
  std::unique_ptr<Fonts> fonts;
  for (;;) {
    Job job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) break;  // stopping, and nothing left
      job = std::move(queue_.front());
      queue_.pop_front();
      busy_ = true;
    }
    std::string line;
    bool ok = true;
    try {
      if (!stage)
        stage = std::make_unique<Stage>(picture_options_.cell_width, picture_options_.cell_height,
                                        picture_options_.samples);
      if (job.is_video) {
        const VideoStats s = render_video(job.subject, video_options_, job.path, {}, stage.get());
        char buf[160];
        std::snprintf(buf, sizeof buf, " (%d frames, generation %d, genome %lld, fitness %.3f)", s.frames,
                      job.subject.card.generation, static_cast<long long>(job.subject.card.genome_id),
                      job.subject.card.fitness);
        line = "video " + job.path + buf;
      } else {
        if (!fonts) fonts = std::make_unique<Fonts>(Fonts::load(picture_options_.font_size, picture_options_.font_dir));
        write_png(job.path, render_card_with_caption(*stage, *fonts, job.card, picture_options_));
        char buf[160];
        std::snprintf(buf, sizeof buf, " (generation %d, genome %lld, fitness %.3f)", job.card.generation,
                      static_cast<long long>(job.card.genome_id), job.card.fitness);
        line = "picture " + job.path + buf;
      }
    } catch (const std::exception& e) {
      ok = false;
      line = "failed: " + job.path + ": " + e.what();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!ok)
        ++counts_.failures;
      else if (job.is_video)
        ++counts_.videos;
      else
        ++counts_.pictures;
      busy_ = false;
    }
    idle_.notify_all();
    if (report_) report_(line);
  }
  idle_.notify_all();
}

}  // namespace robozoo::render
