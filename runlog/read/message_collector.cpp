#include "runlog/read/message_collector.hpp"

#include <cmath>
#include <exception>

#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"

namespace robozoo {

namespace {

bool finite3(const double v[3]) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

template <class T>
bool decode(const void* data, size_t size, T& out, std::string* why) {
  out = T{};
  return safe_decode(data, size, out, why);
}

}  // namespace

std::string morphology_problem(const morphology_t& m) {
  if (m.num_spheres < 1) return "morphology has no sphere";
  if (static_cast<int32_t>(m.spheres.size()) != m.num_spheres)
    return "morphology sphere array size differs from num_spheres";
  if (m.num_bodies < 1 || m.num_bodies > m.num_spheres)
    return "morphology has " + std::to_string(m.num_bodies) + " bodies for " + std::to_string(m.num_spheres) +
           " spheres";
  if (m.num_neurons < 0 || m.num_sensors < 0 || static_cast<int32_t>(m.tau.size()) != m.num_neurons ||
      static_cast<int32_t>(m.omega.size()) != m.num_neurons ||
      static_cast<int32_t>(m.sensor_sphere.size()) != m.num_sensors)
    return "morphology neuron or sensor arrays differ from their counts";
  for (int32_t i = 0; i < m.num_spheres; ++i) {
    const sphere_t& s = m.spheres[static_cast<size_t>(i)];
    if (s.index != i) return "sphere " + std::to_string(i) + " has index " + std::to_string(s.index);
    if (i == 0 ? s.parent != -1 : (s.parent < 0 || s.parent >= i))
      return "sphere " + std::to_string(i) + " has parent " + std::to_string(s.parent);
    if (!(s.radius > 0) || !std::isfinite(s.radius) || !finite3(s.center))
      return "sphere " + std::to_string(i) + " has a bad radius or centre";
    if (s.body < 0 || s.body >= m.num_bodies)
      return "sphere " + std::to_string(i) + " is in body " + std::to_string(s.body) + " of " +
             std::to_string(m.num_bodies);
  }
  for (int32_t k = 0; k < m.num_sensors; ++k)
    if (m.sensor_sphere[static_cast<size_t>(k)] < 0 || m.sensor_sphere[static_cast<size_t>(k)] >= m.num_spheres)
      return "sensor " + std::to_string(k) + " sits on no sphere";
  return "";
}

std::string pose_problem(const pose_t& p, const morphology_t& m) {
  if (p.num_spheres != m.num_spheres || p.num_bodies != m.num_bodies || p.num_neurons != m.num_neurons ||
      p.num_sensors != m.num_sensors)
    return "pose of genome " + std::to_string(p.genome_id) + " has " + std::to_string(p.num_spheres) + " spheres, " +
           std::to_string(p.num_bodies) + " bodies, " + std::to_string(p.num_neurons) + " neurons, " +
           std::to_string(p.num_sensors) + " sensors; its morphology " + std::to_string(m.num_spheres) + ", " +
           std::to_string(m.num_bodies) + ", " + std::to_string(m.num_neurons) + ", " + std::to_string(m.num_sensors);
  if (static_cast<int32_t>(p.sphere_center.size()) != p.num_spheres)
    return "pose sphere array differs from num_spheres";
  if (p.step < 0 || !std::isfinite(p.sim_time)) return "pose has a bad step or time";
  for (const auto& c : p.sphere_center)
    if (!finite3(c.data())) return "pose of genome " + std::to_string(p.genome_id) + " has a non-finite centre";
  return "";
}

MessageCollector::MessageCollector(CollectorOptions options) : options_(options) {}

void MessageCollector::problem(int64_t& counter, const std::string& what) {
  ++counter;
  if (stats_.problems.size() < options_.max_problems) stats_.problems.push_back(what);
}

RunRecord* MessageCollector::find_run(const std::string& run_id) const {
  for (const auto& r : runs_)
    if (r->run.run_id == run_id) return r.get();
  return nullptr;
}

bool MessageCollector::has_open_stream() const {
  for (const auto& r : runs_)
    for (const auto& g : r->genomes)
      if (g->stream == GenomeRecord::Stream::Open) return true;
  return false;
}

void MessageCollector::complete(RunRecord& run, GenomeRecord& g) {
  g.stream = GenomeRecord::Stream::Complete;
  ++stats_.streams_completed;
  if (!on_stream_) return;
  try {
    on_stream_(run, g);
  } catch (const std::exception& e) {
    problem(stats_.inconsistent, std::string("handling a completed pose stream failed: ") + e.what());
  } catch (...) {
    problem(stats_.inconsistent, "handling a completed pose stream failed");
  }
}

void MessageCollector::close_streams(RunRecord& run, const GenomeRecord* except) {
  for (auto& g : run.genomes)
    if (g.get() != except && g->stream == GenomeRecord::Stream::Open) complete(run, *g);
}

void MessageCollector::close_open_streams() noexcept {
  for (auto& r : runs_) close_streams(*r, nullptr);
}

void MessageCollector::ingest(const std::string& channel, const void* data, size_t size,
                              const std::string& source) noexcept {
  ++stats_.messages;
  try {
    if (channel == kChannelRun)
      handle_run(data, size, source);
    else if (channel == kChannelGeneration)
      handle_generation(data, size);
    else if (channel == kChannelGenome)
      handle_genome(data, size);
    else if (channel == kChannelMorphology)
      handle_morphology(data, size);
    else if (channel == kChannelPose)
      handle_pose(data, size);
    else
      ++stats_.other_channels;
  } catch (const std::exception& e) {  // out of memory, a callback's failure: never out of here
    problem(stats_.inconsistent, channel + ": " + e.what());
  } catch (...) {
    problem(stats_.inconsistent, channel + ": unknown failure");
  }
}

void MessageCollector::handle_run(const void* data, size_t size, const std::string& source) {
  run_t m;
  std::string why;
  if (!decode(data, size, m, &why)) return problem(stats_.undecodable, std::string(kChannelRun) + ": " + why);
  if (m.steps < 1 || !(m.dt > 0) || m.regime < 0 || m.regime > 1)
    return problem(stats_.inconsistent, "run " + m.run_id + ": bad steps, dt or regime");
  RunRecord* run = find_run(m.run_id);
  if (!run) {
    runs_.push_back(std::make_unique<RunRecord>());
    run = runs_.back().get();
    run->source = source;
  } else {
    close_streams(*run, nullptr);
  }
  run->run = std::move(m);
  ++stats_.accepted;
  if (on_run_) on_run_(*run);
}

void MessageCollector::handle_generation(const void* data, size_t size) {
  generation_t m;
  std::string why;
  if (!decode(data, size, m, &why)) return problem(stats_.undecodable, std::string(kChannelGeneration) + ": " + why);
  RunRecord* run = find_run(m.run_id);
  if (!run) {
    ++stats_.before_run;
    return;
  }
  if (m.generation < 0)
    return problem(stats_.inconsistent, "generation_t with generation " + std::to_string(m.generation));
  close_streams(*run, nullptr);
  run->generations.push_back(std::move(m));
  ++stats_.accepted;
  if (on_generation_) on_generation_(*run);
}

void MessageCollector::handle_genome(const void* data, size_t size) {
  cppn_genome_t m;
  std::string why;
  if (!decode(data, size, m, &why)) return problem(stats_.undecodable, std::string(kChannelGenome) + ": " + why);
  RunRecord* run = find_run(m.run_id);
  if (!run) {
    ++stats_.before_run;
    return;
  }
  if (!std::isfinite(m.fitness) || m.generation < 0)
    return problem(stats_.inconsistent, "genome " + std::to_string(m.genome_id) + ": bad fitness or generation");
  close_streams(*run, nullptr);
  GenomeRecord* g = run->find(m.genome_id);
  if (!g) {
    run->genomes.push_back(std::make_unique<GenomeRecord>());
    g = run->genomes.back().get();
    run->by_id[m.genome_id] = g;
  }
  const generation_t* gen = run->generation(m.generation);
  g->champion = gen ? gen->champion_id == m.genome_id : true;
  g->genome = std::move(m);
  ++stats_.accepted;
}

void MessageCollector::handle_morphology(const void* data, size_t size) {
  morphology_t m;
  std::string why;
  if (!decode(data, size, m, &why)) return problem(stats_.undecodable, std::string(kChannelMorphology) + ": " + why);
  RunRecord* run = find_run(m.run_id);
  if (!run) {
    ++stats_.before_run;
    return;
  }
  GenomeRecord* g = run->find(m.genome_id);
  if (!g) return problem(stats_.orphans, "morphology of genome " + std::to_string(m.genome_id) + " before its genome");
  const std::string bad = morphology_problem(m);
  if (!bad.empty())
    return problem(stats_.inconsistent, "morphology of genome " + std::to_string(m.genome_id) + ": " + bad);
  g->morphology = std::move(m);
  g->has_morphology = true;
  ++stats_.accepted;
  if (g->champion && on_champion_) on_champion_(*run, *g);
}

void MessageCollector::handle_pose(const void* data, size_t size) {
  pose_t m;
  std::string why;
  if (!decode(data, size, m, &why)) return problem(stats_.undecodable, std::string(kChannelPose) + ": " + why);
  RunRecord* run = find_run(m.run_id);
  if (!run) {
    ++stats_.before_run;
    return;
  }
  GenomeRecord* g = run->find(m.genome_id);
  if (!g || !g->has_morphology)
    return problem(stats_.orphans, "pose of genome " + std::to_string(m.genome_id) + " before its morphology");
  const std::string bad = pose_problem(m, g->morphology);
  if (!bad.empty()) return problem(stats_.inconsistent, bad);
  if (g->stream == GenomeRecord::Stream::Complete)
    return problem(stats_.inconsistent, "pose of genome " + std::to_string(m.genome_id) + " after its stream ended");
  if (g->stream == GenomeRecord::Stream::Open && m.step <= g->last_step)
    return problem(stats_.inconsistent, "pose of genome " + std::to_string(m.genome_id) + " step " +
                                            std::to_string(m.step) + " after step " + std::to_string(g->last_step));
  if (g->stream == GenomeRecord::Stream::None) {
    close_streams(*run, g);  // streams follow one another
    g->stream = GenomeRecord::Stream::Open;
  }
  ++g->pose_count;
  g->last_step = m.step;
  if (options_.keep_poses) g->poses.push_back(std::move(m));
  ++stats_.accepted;
  if (on_pose_) on_pose_(*run, *g, options_.keep_poses ? g->poses.back() : m);
  if (g->last_step >= run->run.steps) complete(*run, *g);
}

}  // namespace robozoo
