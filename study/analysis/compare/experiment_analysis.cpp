#include "study/analysis/compare/experiment_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace robozoo {

Comparison compare(const std::string& key, const std::string& label, const std::string& unit,
                   const std::vector<double>& control, const std::vector<double>& experimental, Samples samples) {
  Comparison c;
  c.key = key;
  c.label = label;
  c.unit = unit;
  c.control = describe(control);
  c.experimental = describe(experimental);
  c.samples = samples;
  if (samples == Samples::Runs) {
    c.student = ttest_ind(experimental, control);
    c.welch = welch_ttest(experimental, control);
    c.effect = effect_size(experimental, control);
  } else {
    const double nan = std::nan("");
    c.student = c.welch = {nan, nan, nan};
    c.effect.d = c.effect.g = c.effect.d_low = c.effect.d_high = nan;
  }
  c.stars = significance_stars(c.student.p);
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
std::vector<double> pooled(const std::vector<RunAnalysis>& runs, const std::function<bool(const ChampionChange&)>& keep,
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
    const auto c = at(e.control), x = at(e.experimental);
    e.fitness_curve.push_back({static_cast<int32_t>(g), describe(c), describe(x), ttest_ind(x, c)});
  }
  e.last_generation = static_cast<int32_t>(longest) - 1;

  // A run with no logged generation has no fitness: it is left out of that sample.
  auto final_best = [](const std::vector<RunAnalysis>& side) {
    std::vector<double> v;
    for (const auto& r : side)
      if (!r.best_so_far.empty()) v.push_back(r.best_so_far.back());
    return v;
  };
  e.fitness = {compare("best_fitness", "best-of-run fitness (best so far at the last logged generation)",
                       "fitness units", final_best(e.control), final_best(e.experimental))};
  for (size_t i = 0; i < e.other.size();) {  // `other` is sorted by arm
    size_t j = i;
    std::vector<RunAnalysis> arm;
    while (j < e.other.size() && e.other[j].arm == e.other[i].arm) arm.push_back(e.other[j++]);
    e.other_arms.push_back({e.other[i].arm, compare("best_fitness", "best-of-run fitness", "fitness units",
                                                    final_best(e.control), final_best(arm))});
    i = j;
  }

  const std::vector<Spec> morph = {
      {"spheres", "spheres", "count", [](const RunAnalysis& r) { return r.morphology.spheres; }},
      {"leaves", "leaves", "count", [](const RunAnalysis& r) { return r.morphology.leaves; }},
      {"joints", "joints", "count", [](const RunAnalysis& r) { return r.morphology.joints; }},
      {"distance_sensors", "distance sensors", "count",
       [](const RunAnalysis& r) { return r.morphology.distance_sensors; }},
      {"touch_sensors", "touch sensors", "count", [](const RunAnalysis& r) { return r.morphology.touch_sensors; }},
      {"distance_per_sphere", "share of a robot's spheres with a distance sensor", "share",
       [](const RunAnalysis& r) {
         return r.morphology.spheres > 0 ? r.morphology.distance_sensors / r.morphology.spheres : 0.0;
       }},
      {"touch_per_sphere", "share of a robot's spheres with a touch sensor", "share",
       [](const RunAnalysis& r) {
         return r.morphology.spheres > 0 ? r.morphology.touch_sensors / r.morphology.spheres : 0.0;
       }},
      {"hit_max_spheres", "best-of-run robots that hit max_spheres (share)", "share",
       [](const RunAnalysis& r) { return r.max_spheres > 0 && r.morphology.spheres >= r.max_spheres ? 1.0 : 0.0; }},
      {"proprio_sensors", "proprioceptive sensors", "count",
       [](const RunAnalysis& r) { return r.morphology.proprio_sensors; }},
      {"time_sensors", "time sensors", "count", [](const RunAnalysis& r) { return r.morphology.time_sensors; }},
      {"mean_radius", "mean radius", "m", [](const RunAnalysis& r) { return r.morphology.mean_radius; }},
      {"radius_variance", "radius variance within a robot", "m^2",
       [](const RunAnalysis& r) { return r.morphology.radius_variance; }},
      {"max_depth", "maximum depth from the root", "count",
       [](const RunAnalysis& r) { return r.morphology.max_depth; }},
      {"ground_spheres", "spheres that touched the ground", "count",
       [](const RunAnalysis& r) { return r.morphology.ground_spheres; }},
      {"ground_fraction", "fraction of spheres that touched the ground", "share",
       [](const RunAnalysis& r) { return r.morphology.ground_fraction; }},
  };
  e.morphology = compare_all(morph, e, true);

  const std::vector<Spec> geno = {
      {"nodes", "nodes", "count", [](const RunAnalysis& r) { return r.genotype.nodes; }},
      {"hidden_sigmoid", "hidden sigmoid nodes", "count",
       [](const RunAnalysis& r) { return r.genotype.hidden_sigmoid; }},
      {"hidden_cosine", "hidden cosine nodes", "count", [](const RunAnalysis& r) { return r.genotype.hidden_cosine; }},
      {"hidden_gaussian", "hidden Gaussian nodes", "count",
       [](const RunAnalysis& r) { return r.genotype.hidden_gaussian; }},
      {"links", "links (enabled)", "count", [](const RunAnalysis& r) { return r.genotype.links; }},
      {"forward_links", "forward links (position of source < target)", "count",
       [](const RunAnalysis& r) { return r.genotype.forward_links; }},
      {"hidden", "hidden nodes", "count", [](const RunAnalysis& r) { return r.genotype.hidden; }},
      {"recurrent_links", "recurrent links (not forward)", "count",
       [](const RunAnalysis& r) { return r.genotype.recurrent_links; }},
      {"cycle_links", "links on a directed cycle", "count",
       [](const RunAnalysis& r) { return r.genotype.cycle_links; }},
  };
  e.genotype = compare_all(geno, e, true);

  auto all = [](const ChampionChange&) { return true; };
  auto changed = [](const ChampionChange& c) { return c.topology_changed; };
  auto same = [](const ChampionChange& c) { return !c.topology_changed; };
  auto indicator = [](const ChampionChange& c) { return c.topology_changed ? 1.0 : 0.0; };
  auto gain = [](const ChampionChange& c) { return c.improvement; };
  // Per run: the mean of `value` over the run's new champions that `keep`
  // selects; runs without any such champion have no value.
  auto per_run = [](const std::vector<RunAnalysis>& side, const std::function<bool(const ChampionChange&)>& keep,
                    const std::function<double(const ChampionChange&)>& value) {
    std::vector<double> v;
    for (const auto& r : side) {
      double sum = 0;
      int n = 0;
      for (const auto& c : r.changes.changes)
        if (keep(c)) {
          sum += value(c);
          ++n;
        }
      if (n > 0) v.push_back(sum / n);
    }
    return v;
  };
  auto per_run_count = [](const std::vector<RunAnalysis>& side) {
    std::vector<double> v;
    for (const auto& r : side) v.push_back(static_cast<double>(r.changes.changes.size()));
    return v;
  };
  const auto& C = e.control;
  const auto& X = e.experimental;
  e.champion = {
      compare("topology_changed_per_run",
              "share of a run's new champions whose topology differs from the previous "
              "champion's (per run)",
              "share", per_run(C, all, indicator), per_run(X, all, indicator)),
      compare("improvement_changed_per_run",
              "a run's mean fitness gain of its new champions with a different "
              "topology (per run)",
              "fitness units", per_run(C, changed, gain), per_run(X, changed, gain)),
      compare("improvement_same_per_run",
              "a run's mean fitness gain of its new champions with the same topology "
              "(per run)",
              "fitness units", per_run(C, same, gain), per_run(X, same, gain)),
      compare("new_champions_per_run", "new champions per run", "count", per_run_count(C), per_run_count(X)),
      compare("topology_changed", "new champions whose topology differs from the previous champion's (pooled)", "share",
              pooled(C, all, indicator), pooled(X, all, indicator), Samples::PooledEvents),
      compare("improvement_changed", "fitness gain of a new champion with a different topology (pooled)",
              "fitness units", pooled(C, changed, gain), pooled(X, changed, gain), Samples::PooledEvents),
      compare("improvement_same", "fitness gain of a new champion with the same topology (pooled)", "fitness units",
              pooled(C, same, gain), pooled(X, same, gain), Samples::PooledEvents),
      compare("improvement_all", "fitness gain of any new champion (pooled)", "fitness units", pooled(C, all, gain),
              pooled(X, all, gain), Samples::PooledEvents),
  };
  for (const auto& r : e.control) e.control_without_poses += r.has_best && !r.morphology.ground_known;
  for (const auto& r : e.experimental) e.experimental_without_poses += r.has_best && !r.morphology.ground_known;
  auto at_cap = [](const RunAnalysis& r) {
    return r.has_best && r.max_spheres > 0 && r.morphology.spheres >= r.max_spheres;
  };
  for (const auto& r : e.control) e.control_at_cap += at_cap(r);
  for (const auto& r : e.experimental) e.experimental_at_cap += at_cap(r);
  for (auto& c : e.morphology)
    if (censored_by_sphere_cap(c.key)) {
      c.control_at_cap = e.control_at_cap;
      c.experimental_at_cap = e.experimental_at_cap;
    }
  return e;
}

std::string arm_title(const std::string& arm) {
  if (arm == "feedforward") return "feed-forward";
  if (arm == "recurrent-sparse") return "recurrent (sparse start)";
  if (arm == "recurrent-zero") return "recurrent (zero-weight start)";
  return arm;
}

bool censored_by_sphere_cap(const std::string& key) {
  for (const char* k : {"spheres", "leaves", "joints", "distance_sensors", "touch_sensors", "proprio_sensors",
                        "time_sensors", "max_depth", "ground_spheres"})
    if (key == k) return true;
  return false;
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
