#include "view/feed/bus_feed.hpp"

#include <chrono>
#include <stdexcept>

#include <lcm/lcm-cpp.hpp>

#include "evolve/io/bus.hpp"

namespace robozoo::view {

namespace {

using Clock = std::chrono::steady_clock;

struct Subscriber {
  ViewState* state;
  Clock::time_point last = Clock::now();
  bool any = false;
  // A plain function, not a member: see render/live.cpp (GCC 12's sanitizers and
  // LCM's call through a pointer to member function).
  static void on_message(const lcm::ReceiveBuffer* rbuf, const std::string& channel, Subscriber* self) {
    self->state->ingest(channel, rbuf->data, rbuf->data_size);  // never throws
    self->last = Clock::now();
    self->any = true;
  }
};

}  // namespace

void follow_bus(const BusFeedOptions& o, ViewState& state, const std::function<bool()>& should_stop,
                std::ostream& log) {
  Bus bus(o.url);  // throws naming the URL
  Subscriber sub{&state};
  lcm::Subscription* subscription = bus.lcm().subscribeFunction("ROBOZOO_.*", &Subscriber::on_message, &sub);
  // LCM's receiving thread queues whole messages for this one and drops any
  // beyond the subscription's capacity, 30 by default: a stall of some 40 ms
  // (a busy machine) in the middle of a champion's pose stream lost poses.
  if (subscription) subscription->setQueueCapacity(o.queue_messages);
  log << "robozoo-view: listening on " << o.url << std::endl;
  std::string run_seen;
  int64_t bad_seen = 0;
  const auto started = Clock::now();
  while (!should_stop()) {
    if (bus.lcm().handleTimeout(100) < 0) throw std::runtime_error("LCM stopped reading " + o.url);
    const ViewCounters c = state.counters();
    if (c.run_id != run_seen) {
      log << "robozoo-view: following run " << c.run_id << std::endl;
      run_seen = c.run_id;
    }
    if (c.bad > bad_seen) {
      log << "robozoo-view: skipped " << (c.bad - bad_seen) << " bad message(s) (" << c.bad << " so far)" << std::endl;
      bad_seen = c.bad;
    }
    const double quiet = std::chrono::duration<double>(Clock::now() - (sub.any ? sub.last : started)).count();
    if (quiet > o.stream_timeout && state.has_open_stream()) state.end_of_input();
    if (o.idle_exit > 0 && !run_seen.empty() && quiet > o.idle_exit) {
      log << "robozoo-view: no message for " << o.idle_exit << " s: finishing" << std::endl;
      return;
    }
  }
}

}  // namespace robozoo::view
