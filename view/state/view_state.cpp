#include "view/state/view_state.hpp"

#include <algorithm>

#include "runlog/robots/selection.hpp"
#include "runlog/robots/trajectory.hpp"

namespace robozoo::view {

ViewState::ViewState(std::string mode, std::string source, ViewStateOptions options)
    : mode_(std::move(mode)), source_(std::move(source)), options_(options) {
  install_callbacks();
}

void ViewState::install_callbacks() {
  collector_ = std::make_unique<MessageCollector>();
  collector_->on_run([this](const RunRecord& r) { handle_run(r); });
  collector_->on_generation([this](const RunRecord& r) { handle_generation(r); });
  collector_->on_champion([this](const RunRecord& r, const GenomeRecord& g) { handle_champion(r, g); });
  collector_->on_pose([this](const RunRecord& r, const GenomeRecord& g, const pose_t& p) { handle_pose(r, g, p); });
  collector_->on_stream_complete([this](const RunRecord& r, GenomeRecord& g) { handle_stream_end(r, g); });
}

void ViewState::ingest(const std::string& channel, const void* data, size_t size) noexcept {
  std::lock_guard<std::mutex> lock(mutex_);
  collector_->ingest(channel, data, size);
}

void ViewState::end_of_input() noexcept {
  std::lock_guard<std::mutex> lock(mutex_);
  collector_->close_open_streams();
}

void ViewState::restart() {
  std::lock_guard<std::mutex> lock(mutex_);
  reset_run_locked();
  run_id_.clear();
  run_frame_ = nullptr;
  install_callbacks();
}

bool ViewState::has_open_stream() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return collector_->has_open_stream();
}

void ViewState::reset_run_locked() {
  history_.clear();
  champions_.clear();
  have_champion_ = false;
  shown_id_ = -1;
  robot_frame_ = nullptr;
  shown_poses_ = nlohmann::json::array();
  shown_done_ = false;
  completed_.clear();
  poses_ = 0;
}

void ViewState::push_locked(Client& c, const Frame& f, bool is_pose) {
  if (c.queue.push(f, is_pose) && c.wake) c.wake();
}

void ViewState::broadcast_locked(const Frame& f, bool is_pose) {
  if (quiet_) return;
  for (const auto& c : clients_) push_locked(*c, f, is_pose);
}

void ViewState::set_quiet(bool quiet) {
  std::lock_guard<std::mutex> lock(mutex_);
  const bool was = quiet_;
  quiet_ = quiet;
  if (was && !quiet)
    for (const auto& c : clients_) push_snapshot_locked(*c);
}

void ViewState::handle_run(const RunRecord& run) {
  if (run.run.run_id == run_id_) {
    return;  // evolve repeats ROBOZOO_RUN every generation
  }
  // A run seen for the first time: the view follows it from now on.
  if (!run_id_.empty() && !run.generations.empty()) return;  // an old run repeated, not a new one
  reset_run_locked();
  run_id_ = run.run.run_id;
  double target[3] = {0, 0, 0};
  try {
    const Eigen::Vector3d t = run_target(run.run);
    for (int k = 0; k < 3; ++k) target[k] = t[k];
  } catch (const std::exception&) {
    // A configuration that does not parse: the target is drawn at the origin.
  }
  run_frame_ = run_json(run.run, target);
  broadcast_locked(make_frame(run_frame_), false);
}

void ViewState::handle_generation(const RunRecord& run) {
  if (run.run.run_id != run_id_) return;
  history_.push_back(generation_json(run.generations.back()));
  broadcast_locked(make_frame(history_.back()), false);
}

void ViewState::handle_champion(const RunRecord& run, const GenomeRecord& g) {
  if (run.run.run_id != run_id_) return;
  const uint64_t genes = gene_hash(g.genome);
  if (have_champion_ && genes == last_champion_genes_) return;
  have_champion_ = true;
  last_champion_genes_ = genes;
  champions_.push_back(champion_json(g.genome));
  broadcast_locked(make_frame(champions_.back()), false);
}

void ViewState::handle_pose(const RunRecord& run, const GenomeRecord& g, const pose_t& p) {
  if (run.run.run_id != run_id_) return;
  if (g.genome.genome_id != shown_id_) {
    shown_id_ = g.genome.genome_id;
    robot_frame_ = robot_json(g.genome, g.morphology, true, false);
    shown_poses_ = nlohmann::json::array();
    shown_done_ = false;
    broadcast_locked(make_frame(robot_frame_), false);
  }
  nlohmann::json j = pose_json(p);
  const Frame f = make_frame(j);
  j.erase("t");
  shown_poses_.push_back(std::move(j));
  ++poses_;
  broadcast_locked(f, true);
}

void ViewState::handle_stream_end(const RunRecord& run, GenomeRecord& g) {
  if (run.run.run_id == run_id_ && g.genome.genome_id == shown_id_ && !shown_done_) {
    shown_done_ = true;
    broadcast_locked(make_frame({{"t", "end"}, {"id", shown_id_}}), false);
  }
  if (options_.keep_streams == 0 || g.poses.empty()) return;
  completed_.push_back(&g);
  if (completed_.size() > options_.keep_streams) {
    GenomeRecord* old = completed_.front();
    completed_.erase(completed_.begin());
    old->poses.clear();
    old->poses.shrink_to_fit();
  }
}

void ViewState::push_snapshot_locked(Client& c) {
  push_locked(c, make_frame(hello_json(mode_, source_)), false);
  if (run_frame_.is_null()) return;
  push_locked(c, make_frame(run_frame_), false);
  push_locked(c, make_frame({{"t", "history"}, {"gens", history_}}), false);
  push_locked(c, make_frame({{"t", "champions"}, {"list", champions_}}), false);
  if (robot_frame_.is_null()) return;
  push_locked(c, make_frame(robot_frame_), false);
  push_locked(
      c,
      make_frame(
          {{"t", "poses"}, {"id", shown_id_}, {"list", shown_poses_}, {"done", shown_done_}, {"resimulated", false}}),
      false);
}

std::shared_ptr<Client> ViewState::join(std::function<void()> wake) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto c = std::make_shared<Client>(options_.queue);
  c->id = next_client_++;
  push_snapshot_locked(*c);
  c->wake = std::move(wake);
  clients_.push_back(c);
  if (c->wake) c->wake();
  return c;
}

void ViewState::leave(const std::shared_ptr<Client>& client) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = std::find(clients_.begin(), clients_.end(), client);
  if (it == clients_.end()) return;
  const QueueCounters q = client->queue.counters();
  dropped_by_departed_ += q.dropped_poses;
  given_up_ += q.overflowed;
  clients_.erase(it);
}

ReplayPlan ViewState::plan_replay(int64_t genome_id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  ReplayPlan plan;
  const RunRecord* run = nullptr;
  for (const auto& r : collector_->runs())
    if (r->run.run_id == run_id_) run = r.get();
  const GenomeRecord* g = run ? run->find(genome_id) : nullptr;
  if (!g || !g->has_morphology) {
    plan.error = "genome " + std::to_string(genome_id) + " is not a champion of the run shown";
    return plan;
  }
  if (const GenomeRecord* source = logged_pose_source(*run, *g)) {
    const Trajectory t = trajectory_from_poses(source->poses, g->morphology.spheres.size());
    plan.frames.push_back(make_frame(robot_json(g->genome, g->morphology, false, true)));
    plan.frames.push_back(make_frame(trajectory_json(genome_id, t)));
    return plan;
  }
  plan.run = run->run;
  plan.genome = g->genome;
  plan.morphology = g->morphology;
  return plan;
}

std::vector<Frame> ViewState::resimulate(const ReplayPlan& plan) const {
  const Trajectory t = simulate_trajectory(*plan.run, *plan.genome, *plan.morphology, options_.resimulate_every);
  return {make_frame(robot_json(*plan.genome, *plan.morphology, false, true)),
          make_frame(trajectory_json(plan.genome->genome_id, t))};
}

ViewCounters ViewState::counters() const {
  std::lock_guard<std::mutex> lock(mutex_);
  ViewCounters v;
  const CollectorStats& s = collector_->stats();
  v.messages = s.messages;
  v.bad = s.rejected();
  v.generations = static_cast<int64_t>(history_.size());
  v.champions = static_cast<int64_t>(champions_.size());
  v.poses = poses_;
  v.dropped_poses = dropped_by_departed_;
  v.pages_given_up = given_up_;
  for (const auto& c : clients_) {
    const QueueCounters q = c->queue.counters();
    v.dropped_poses += q.dropped_poses;
    v.pages_given_up += q.overflowed;
  }
  v.pages = static_cast<int64_t>(clients_.size());
  v.run_id = run_id_;
  return v;
}

Frame ViewState::stats_frame(const Client& client) const {
  const ViewCounters v = counters();
  const QueueCounters q = client.queue.counters();
  return make_frame({{"t", "stats"},
                     {"dropped", q.dropped_poses},
                     {"waiting", q.waiting},
                     {"bad", v.bad},
                     {"messages", v.messages},
                     {"pages", v.pages},
                     {"dropped_all", v.dropped_poses}});
}

}  // namespace robozoo::view
