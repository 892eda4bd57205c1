#include "evolve/analysis/experiment_analysis.hpp"

#include <algorithm>
#include <functional>

namespace robozoo {

Comparison compare(const std::string& key, const std::string& label, const std::string& unit,
                   const std::vector<double>& control, const std::vector<double>& experimental) {
  Comparison c;
  c.key = key;
  c.label = label;
  c.unit = unit;
  c.control = describe(control);
  c.experimental = describe(experimental);
  c.test = ttest_ind(control, experimental);
  c.stars = significance_stars(c.test.p);
  return c;
}

namespace {

using RunValue = std::function<double(const RunAnalysis&)>;

struct Spec {
  const char* key;
  const char* label;
  const char* unit;
  RunValue value;
};

std::vector<double> values(const std::vector<RunAnalysis>& runs, const RunValue& f, bool need_best) {
  std::vector<double> v;
  for (const auto& r : runs)
    if (!need_best || r.has_best) v.push_back(f(r));
  return v;
}

std::vector<Comparison> compare_all(const std::vector<Spec>& specs, const ExperimentAnalysis& e, bool need_best) {
  std::vector<Comparison> out;
  for (const auto& s : specs)
    out.push_back(compare(s.key, s.label, s.unit, values(e.control, s.value, need_best),
                          values(e.experimental, s.value, need_best)));
  return out;
}

// Pooled over the new champions of every run of a regime.
std::vector<double> pooled(const std::vector<RunAnalysis>& runs,
                           const std::function<bool(const ChampionChange&)>& keep,
                           const std::function<double(const ChampionChange&)>& value) {
  std::vector<double> v;
  for (const auto& r : runs)
    for (const auto& c : r.changes.changes)
      if (keep(c)) v.push_back(value(c));
  return v;
}

}  // namespace

ExperimentAnalysis analyze_experiment(std::vector<RunAnalysis> runs, const std::string& control_arm,
                                      const std::string& experimental_arm) {
  ExperimentAnalysis e;
  e.control_arm = control_arm;
  e.experimental_arm = experimental_arm;
  std::sort(runs.begin(), runs.end(), [](const RunAnalysis& a, const RunAnalysis& b) {
    return a.arm != b.arm ? a.arm < b.arm : a.seed != b.seed ? a.seed < b.seed : a.path < b.path;
  });
  for (auto& r : runs)
    (r.arm == control_arm ? e.control : r.arm == experimental_arm ? e.experimental : e.other).push_back(std::move(r));

  size_t longest = 0;
  for (const auto* side : {&e.control, &e.experimental})
    for (const auto& r : *side) longest = std::max(longest, r.best_so_far.size());
  for (size_t g = 0; g < longest; ++g) {
    auto at = [g](const std::vector<RunAnalysis>& side) {
      std::vector<double> v;
      for (const auto& r : side)
        if (g < r.best_so_far.size()) v.push_back(r.best_so_far[g]);
      return v;
    };
    e.fitness_curve.push_back({static_cast<int32_t>(g), describe(at(e.control)), describe(at(e.experimental))});
  }

  // A run with no logged generation has no fitness: it is left out of that sample.
  auto final_best = [](const std::vector<RunAnalysis>& side) {
    std::vector<double> v;
    for (const auto& r : side)
      if (!r.best_so_far.empty()) v.push_back(r.best_so_far.back());
    return v;
  };
  e.fitness = {compare("best_fitness", "best-of-run fitness (best so far at the last logged generation)",
                       "fitness units", final_best(e.control), final_best(e.experimental))};

  const std::vector<Spec> morph = {
      {"spheres", "spheres", "count", [](const RunAnalysis& r) { return r.morphology.spheres; }},
      {"leaves", "leaves", "count", [](const RunAnalysis& r) { return r.morphology.leaves; }},
      {"joints", "joints", "count", [](const RunAnalysis& r) { return r.morphology.joints; }},
      {"distance_sensors", "distance sensors", "count", [](const RunAnalysis& r) { return r.morphology.distance_sensors; }},
      {"touch_sensors", "touch sensors", "count", [](const RunAnalysis& r) { return r.morphology.touch_sensors; }},
      {"distance_per_sphere", "share of a robot's spheres with a distance sensor", "share",
       [](const RunAnalysis& r) { return r.morphology.spheres > 0 ? r.morphology.distance_sensors / r.morphology.spheres : 0.0; }},
      {"touch_per_sphere", "share of a robot's spheres with a touch sensor", "share",
       [](const RunAnalysis& r) { return r.morphology.spheres > 0 ? r.morphology.touch_sensors / r.morphology.spheres : 0.0; }},
      {"hit_max_spheres", "best-of-run robots that hit max_spheres (share)", "share",
       [](const RunAnalysis& r) { return r.max_spheres > 0 && r.morphology.spheres >= r.max_spheres ? 1.0 : 0.0; }},
      {"proprio_sensors", "proprioceptive sensors", "count", [](const RunAnalysis& r) { return r.morphology.proprio_sensors; }},
      {"time_sensors", "time sensors", "count", [](const RunAnalysis& r) { return r.morphology.time_sensors; }},
      {"mean_radius", "mean radius", "m", [](const RunAnalysis& r) { return r.morphology.mean_radius; }},
      {"radius_variance", "radius variance within a robot", "m^2", [](const RunAnalysis& r) { return r.morphology.radius_variance; }},
      {"max_depth", "maximum depth from the root", "count", [](const RunAnalysis& r) { return r.morphology.max_depth; }},
      {"ground_spheres", "spheres that touched the ground", "count", [](const RunAnalysis& r) { return r.morphology.ground_spheres; }},
      {"ground_fraction", "fraction of spheres that touched the ground", "share", [](const RunAnalysis& r) { return r.morphology.ground_fraction; }},
  };
  e.morphology = compare_all(morph, e, true);

  const std::vector<Spec> geno = {
      {"nodes", "nodes", "count", [](const RunAnalysis& r) { return r.genotype.nodes; }},
      {"hidden_sigmoid", "hidden sigmoid nodes", "count", [](const RunAnalysis& r) { return r.genotype.hidden_sigmoid; }},
      {"hidden_cosine", "hidden cosine nodes", "count", [](const RunAnalysis& r) { return r.genotype.hidden_cosine; }},
      {"hidden_gaussian", "hidden Gaussian nodes", "count", [](const RunAnalysis& r) { return r.genotype.hidden_gaussian; }},
      {"links", "links (enabled)", "count", [](const RunAnalysis& r) { return r.genotype.links; }},
      {"forward_links", "forward links (position of source < target)", "count", [](const RunAnalysis& r) { return r.genotype.forward_links; }},
      {"hidden", "hidden nodes", "count", [](const RunAnalysis& r) { return r.genotype.hidden; }},
      {"recurrent_links", "recurrent links (not forward)", "count", [](const RunAnalysis& r) { return r.genotype.recurrent_links; }},
      {"cycle_links", "links on a directed cycle", "count", [](const RunAnalysis& r) { return r.genotype.cycle_links; }},
  };
  e.genotype = compare_all(geno, e, true);

  auto all = [](const ChampionChange&) { return true; };
  auto changed = [](const ChampionChange& c) { return c.topology_changed; };
  auto same = [](const ChampionChange& c) { return !c.topology_changed; };
  auto indicator = [](const ChampionChange& c) { return c.topology_changed ? 1.0 : 0.0; };
  auto gain = [](const ChampionChange& c) { return c.improvement; };
  auto per_run_share = [](const std::vector<RunAnalysis>& side) {
    std::vector<double> v;
    for (const auto& r : side) {
      if (r.changes.changes.empty()) continue;
      double k = 0;
      for (const auto& c : r.changes.changes) k += c.topology_changed;
      v.push_back(k / static_cast<double>(r.changes.changes.size()));
    }
    return v;
  };
  auto per_run_count = [](const std::vector<RunAnalysis>& side) {
    std::vector<double> v;
    for (const auto& r : side) v.push_back(static_cast<double>(r.changes.changes.size()));
    return v;
  };
  e.champion = {
      compare("topology_changed", "new champions whose topology differs from the previous champion's (pooled)",
              "share", pooled(e.control, all, indicator), pooled(e.experimental, all, indicator)),
      compare("improvement_changed", "fitness improvement of a new champion with a different topology (pooled)",
              "fitness units", pooled(e.control, changed, gain), pooled(e.experimental, changed, gain)),
      compare("improvement_same", "fitness improvement of a new champion with the same topology (pooled)",
              "fitness units", pooled(e.control, same, gain), pooled(e.experimental, same, gain)),
      compare("improvement_all", "fitness improvement of any new champion (pooled)", "fitness units",
              pooled(e.control, all, gain), pooled(e.experimental, all, gain)),
      compare("topology_changed_per_run", "share of a run's new champions with a different topology (per run)",
              "share", per_run_share(e.control), per_run_share(e.experimental)),
      compare("new_champions_per_run", "new champions per run", "count", per_run_count(e.control),
              per_run_count(e.experimental)),
  };
  for (const auto& r : e.control) e.control_without_poses += r.has_best && !r.morphology.ground_known;
  for (const auto& r : e.experimental) e.experimental_without_poses += r.has_best && !r.morphology.ground_known;
  return e;
}

std::string arm_title(const std::string& arm) {
  if (arm == "feedforward") return "feed-forward";
  if (arm == "recurrent-sparse") return "recurrent (sparse start)";
  if (arm == "recurrent-zero") return "recurrent (start's recurrent links at 0)";
  return arm;
}

std::string arm_column(const std::string& arm) {
  std::string c = arm;
  for (char& ch : c)
    if (ch == '-') ch = '_';
  return c;
}

const Comparison* find_comparison(const std::vector<Comparison>& list, const std::string& key) {
  for (const auto& c : list)
    if (c.key == key) return &c;
  return nullptr;
}

}  // namespace robozoo
