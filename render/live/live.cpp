#include "render/live/live.hpp"

#include <chrono>
#include <filesystem>
#include <mutex>
#include <stdexcept>

#include <lcm/lcm-cpp.hpp>

#include "evolve/io/bus.hpp"
#include "runlog/read/message_collector.hpp"
#include "render/video/render_worker.hpp"
#include "runlog/robots/trajectory.hpp"
#include "render/video/video_subject.hpp"

namespace robozoo::render {

namespace {

using Clock = std::chrono::steady_clock;

struct Subscriber {
  MessageCollector* collector;
  std::string url;
  Clock::time_point last_message = Clock::now();
  bool any_message = false;
  // A plain function, not a member: LCM's subscribe(channel, &Class::method, object)
  // calls through a pointer to member function, which GCC 12 instruments wrongly
  // under -fsanitize=address,undefined (a vptr check, and an ASan shadow check, of a
  // register that path never set: tools/test.sh --sanitize failed every message).
  static void on_message(const lcm::ReceiveBuffer* rbuf, const std::string& channel, Subscriber* self) {
    // Never throws: ingest() counts what it cannot use.
    self->collector->ingest(channel, rbuf->data, rbuf->data_size, self->url);
    self->last_message = Clock::now();
    self->any_message = true;
  }
};

}  // namespace

std::string safe_file_name(const std::string& s) {
  std::string out = s.empty() ? "run" : s;
  for (char& c : out)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
          c == '-'))
      c = '_';
  if (out[0] == '.') out[0] = '_';
  return out;
}

void validate(const LiveOptions& o) {
  if (o.url.empty()) throw std::invalid_argument("live: an LCM URL is needed");
  if (o.out_dir.empty()) throw std::invalid_argument("live: an output folder is needed");
  if (!(o.stream_timeout > 0 && o.stream_timeout <= 3600))
    throw std::invalid_argument("live: stream timeout must be in (0, 3600] s");
  if (!(o.idle_exit >= 0)) throw std::invalid_argument("live: idle exit must be >= 0 s");
  if (o.idle_exit > 0 && o.idle_exit <= o.stream_timeout)
    throw std::invalid_argument("live: idle exit must be longer than the stream timeout");
  validate(o.picture);
  validate(o.video);
}

LiveSummary run_live(const LiveOptions& o, const std::function<bool()>& should_stop, std::ostream& log) {
  validate(o);
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (!std::filesystem::is_directory(o.out_dir))
    throw std::runtime_error(o.out_dir + ": cannot create the output folder");

  std::mutex log_mutex;
  auto say = [&](const std::string& line) {
    std::lock_guard<std::mutex> lock(log_mutex);
    log << "robozoo-render live: " << line << std::endl;
  };

  RenderWorker worker(o.picture, o.video, say);
  MessageCollector collector;
  const std::string latest = o.out_dir + "/latest.png";
  LiveSummary summary;

  collector.on_champion([&](const RunRecord& run, const GenomeRecord& g) {
    ++summary.champions;
    worker.picture(make_card(run, g), latest);
  });
  collector.on_stream_complete([&](const RunRecord& run, GenomeRecord& g) {
    ++summary.streams;
    if (g.poses.empty()) return;
    // A stream that began after we joined mid-stream lacks its start: skip it.
    if (g.poses.front().step != 0) {
      say("skipping the pose stream of genome " + std::to_string(g.genome.genome_id) + ": it starts at step " +
          std::to_string(g.poses.front().step));
    } else {
      VideoSubject subject = make_video_subject(run, g);
      char name[64];
      std::snprintf(name, sizeof name, "_gen%04d_genome%lld.mp4", g.genome.generation,
                    static_cast<long long>(g.genome.genome_id));
      worker.video(std::move(subject), o.out_dir + "/" + safe_file_name(run.run.run_id) + name);
    }
    g.poses.clear();  // the worker has its own copy; a long run would fill memory
    g.poses.shrink_to_fit();
  });

  robozoo::Bus bus(o.url);  // throws naming the URL when LCM cannot start
  Subscriber sub{&collector, o.url};
  lcm::Subscription* subscription = bus.lcm().subscribeFunction("ROBOZOO_.*", &Subscriber::on_message, &sub);
  if (subscription) subscription->setQueueCapacity(kSubscriberQueueMessages);  // LCM's 30 lost poses
  say("listening on " + o.url + ", writing to " + o.out_dir);

  size_t runs_seen = 0;
  int64_t rejected_seen = 0, before_seen = 0;
  const auto started = Clock::now();
  while (!should_stop()) {
    const int r = bus.lcm().handleTimeout(100);
    if (r < 0) throw std::runtime_error("LCM stopped reading " + o.url);
    const CollectorStats& st = collector.stats();
    if (before_seen == 0 && st.before_run > 0) say("joined mid-run: waiting for the next ROBOZOO_RUN");
    before_seen = st.before_run;
    while (runs_seen < collector.runs().size()) {
      const run_t& run = collector.runs()[runs_seen]->run;
      say("run " + run.run_id + " (" + regime_label(run.regime) + ", seed " + std::to_string(run.seed) + ", " +
          std::to_string(run.generations) + " generations)");
      ++runs_seen;
    }
    if (st.rejected() > rejected_seen) {
      say("skipped " + std::to_string(st.rejected() - rejected_seen) +
          " message(s): " + (st.problems.empty() ? std::string("?") : st.problems.back()) + " (" +
          std::to_string(st.undecodable) + " undecodable, " + std::to_string(st.inconsistent) + " inconsistent, " +
          std::to_string(st.orphans) + " orphaned so far)");
      rejected_seen = st.rejected();
    }
    const double quiet =
        std::chrono::duration<double>(Clock::now() - (sub.any_message ? sub.last_message : started)).count();
    if (collector.has_open_stream() && quiet > o.stream_timeout) collector.close_open_streams();
    if (o.idle_exit > 0 && !collector.runs().empty() && quiet > o.idle_exit) {
      say("no message for " + std::to_string(static_cast<int>(o.idle_exit)) + " s: finishing");
      break;
    }
  }
  worker.wait_idle();
  const CollectorStats& st = collector.stats();
  const WorkerCounts wc = worker.counts();
  summary.messages = st.messages;
  summary.rejected = st.rejected();
  summary.before_run = st.before_run;
  summary.runs = static_cast<int64_t>(collector.runs().size());
  summary.pictures = wc.pictures;
  summary.videos = wc.videos;
  summary.failures = wc.failures;
  say(std::to_string(summary.messages) + " messages (" + std::to_string(summary.rejected) + " rejected, " +
      std::to_string(summary.before_run) + " before a run), " + std::to_string(summary.pictures) + " pictures, " +
      std::to_string(summary.videos) + " videos, " + std::to_string(summary.failures) + " failures");
  return summary;
}

}  // namespace robozoo::render
