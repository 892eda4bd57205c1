#include "evolve/record/run_results.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include "evolve/core/json_fields.hpp"
#include "evolve/cppn/activation.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/neat/population_json.hpp"
#include "evolve/record/checkpoint.hpp"

namespace robozoo {

using nlohmann::json;
using namespace json_fields;

namespace {

/// The genes of a logged genome as a Genome, as genome_from_message reads
/// them but without checking them against robozoo's layout: the statistics
/// read any genome (a hand-made log's too). Throws std::invalid_argument for
/// counts that disagree, or a node kind or activation the genome JSON format
/// cannot name.
Genome genes_of(const cppn_genome_t& m) {
  if (m.num_nodes < 0 || static_cast<size_t>(m.num_nodes) != m.nodes.size() || m.num_links < 0 ||
      static_cast<size_t>(m.num_links) != m.links.size())
    throw std::invalid_argument("counts do not match its arrays");
  Genome g;
  g.id = m.genome_id;
  for (const auto& n : m.nodes) {
    if (n.kind < 0 || n.kind > 3)
      throw std::invalid_argument("node " + std::to_string(n.id) + " has unknown kind " + std::to_string(n.kind));
    if (!valid_activation(n.activation))
      throw std::invalid_argument("node " + std::to_string(n.id) + " has unknown activation " +
                                  std::to_string(n.activation));
    g.nodes.push_back({n.id, static_cast<NodeKind>(n.kind), static_cast<Activation>(n.activation), n.position});
  }
  for (const auto& l : m.links) g.links.push_back({l.innovation, l.from_node, l.to_node, l.weight, l.enabled != 0, 0});
  return g;
}

/// The logged genome as it reads back from the genome JSON format: the genes
/// through Genome (genes_of, make_genome_message), the evaluation fields as logged.
cppn_genome_t normalized_genome(const cppn_genome_t& m, const std::string& run_id) {
  const Genome g = genes_of(m);
  cppn_genome_t out = make_genome_message(run_id, m.generation, g, m.species_id, GenomeScore{}, 0);
  out.fitness = m.fitness;
  out.r_term = m.r_term;
  out.d_term = m.d_term;
  out.outcome = m.outcome;
  return out;
}

/// Only the fields of `m` the statistics read: the tree (parents, joints) and,
/// for the best-of-run robot, radii and sensors.
morphology_t reduced_morphology(const morphology_t& m, bool full) {
  morphology_t out{};
  out.generation = m.generation;
  out.genome_id = m.genome_id;
  out.num_spheres = static_cast<int32_t>(m.spheres.size());
  out.spheres.resize(m.spheres.size());
  for (size_t i = 0; i < m.spheres.size(); ++i) {
    sphere_t& s = out.spheres[i];
    s = sphere_t{};
    s.index = static_cast<int32_t>(i);
    s.parent = m.spheres[i].parent;
    s.has_joint = m.spheres[i].has_joint;
    s.motor_neuron = -1;
    if (full) {
      s.radius = m.spheres[i].radius;
      s.sensors = m.spheres[i].sensors;
    }
  }
  return out;
}

json num(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

double read_num(const json& v, const std::string& path) {
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
    fail(path, "not a number");
  }
  return as_double(v, path);
}

template <class T>
json column(const std::vector<GenerationRecord>& gens, T GenerationRecord::*field) {
  json a = json::array();
  for (const auto& g : gens) {
    if constexpr (std::is_same_v<T, double>)
      a.push_back(num(g.*field));
    else
      a.push_back(g.*field);
  }
  return a;
}

const json& array_of(const json& j, const char* key, const std::string& path, size_t n) {
  const json& a = as_array(field(j, key, path), path + "." + key);
  if (n != static_cast<size_t>(-1) && a.size() != n)
    fail(path + "." + key, "has " + std::to_string(a.size()) + " entries, expected " + std::to_string(n));
  return a;
}

}  // namespace

RunSummary compact_summary(const RunSummary& full) {
  RunSummary s;
  s.path = full.path;
  s.run_id = full.run_id;
  s.software_version = full.software_version;
  s.seed = full.seed;
  s.regime = full.regime;
  s.arm = full.arm;
  s.max_spheres = full.max_spheres;
  s.max_d = full.max_d;
  s.target_distance = full.target_distance;
  s.population = full.population;
  s.generations_requested = full.generations_requested;
  s.steps = full.steps;
  s.dt = full.dt;
  s.config_json = full.config_json;
  s.continues = full.continues;
  s.generations = full.generations;
  s.undecodable = full.undecodable;
  s.truncated = full.truncated;
  const ChampionRecord* best = best_of_run(full);
  for (const auto& c : full.champions) {
    ChampionRecord r;
    r.generation = c.generation;
    const bool is_best = &c == best;
    if (is_best) {
      try {
        r.genome = normalized_genome(c.genome, full.run_id);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(full.path + ": the best-of-run genome " + std::to_string(c.genome.genome_id) +
                                    ": " + e.what());
      }
    } else {
      r.genome.run_id = full.run_id;
      r.genome.generation = c.genome.generation;
      r.genome.genome_id = c.genome.genome_id;
      r.genome.species_id = c.genome.species_id;
      r.genome.fitness = c.genome.fitness;
      r.genome.r_term = c.genome.r_term;
      r.genome.d_term = c.genome.d_term;
      r.genome.outcome = c.genome.outcome;
    }
    r.has_morphology = c.has_morphology;
    if (c.has_morphology) r.morphology = reduced_morphology(c.morphology, is_best);
    s.champions.push_back(std::move(r));
  }
  if (best) {
    const auto z = full.min_center_z.find(best->genome.genome_id);
    if (z != full.min_center_z.end()) s.min_center_z.insert(*z);
  }
  return s;
}

json run_results_to_json(const RunResults& res) {
  const RunSummary& s = res.run;
  json j;
  j["format"] = kRunResultsFormat;
  j["version"] = kRunResultsVersion;
  json run;
  run["run_id"] = s.run_id;
  run["log"] = std::filesystem::path(s.path).filename().string();
  run["software_version"] = s.software_version;
  run["seed"] = s.seed;
  run["regime"] = s.regime;
  run["arm"] = s.arm;
  run["population"] = s.population;
  run["generations"] = s.generations_requested;
  run["steps"] = s.steps;
  run["dt"] = num(s.dt);
  const json config = json::parse(s.config_json, nullptr, false);
  run["config"] = config.is_object() ? config : json(s.config_json);  // text that is no JSON object stays text
  j["run"] = std::move(run);
  j["max_d"] = num(s.max_d);
  j["undecodable"] = s.undecodable;
  j["truncated"] = s.truncated;
  j["evolve_seconds"] = res.has_evolve_seconds ? num(res.evolve_seconds) : json(nullptr);
  json g;
  g["generation"] = column(s.generations, &GenerationRecord::generation);
  g["best_fitness"] = column(s.generations, &GenerationRecord::best_fitness);
  g["mean_fitness"] = column(s.generations, &GenerationRecord::mean_fitness);
  g["stderr_fitness"] = column(s.generations, &GenerationRecord::stderr_fitness);
  g["best_so_far_fitness"] = column(s.generations, &GenerationRecord::best_so_far_fitness);
  g["evaluations"] = column(s.generations, &GenerationRecord::evaluations);
  g["champion_id"] = column(s.generations, &GenerationRecord::champion_id);
  g["num_species"] = column(s.generations, &GenerationRecord::num_species);
  g["compatibility_threshold"] = column(s.generations, &GenerationRecord::compatibility_threshold);
  json outcomes = json::array();
  for (const auto& r : s.generations) outcomes.push_back(r.outcomes);
  g["outcomes"] = std::move(outcomes);
  j["generations"] = std::move(g);
  const ChampionRecord* best = best_of_run(s);
  json champs = json::array();
  for (const auto& c : s.champions) {
    json cj;
    cj["generation"] = c.generation;
    cj["genome_id"] = c.genome.genome_id;
    cj["species_id"] = c.genome.species_id;
    cj["fitness"] = num(c.genome.fitness);
    cj["r_term"] = num(c.genome.r_term);
    cj["d_term"] = num(c.genome.d_term);
    cj["outcome"] = c.genome.outcome;
    if (c.has_morphology) {
      json parents = json::array();
      std::string joints;
      for (const auto& sp : c.morphology.spheres) {
        parents.push_back(sp.parent);
        joints += sp.has_joint ? '1' : '0';
      }
      cj["parents"] = std::move(parents);
      cj["joints"] = joints;
    } else {
      cj["parents"] = nullptr;
      cj["joints"] = nullptr;
    }
    champs.push_back(std::move(cj));
  }
  j["champions"] = std::move(champs);
  if (best) {
    json b;
    b["generation"] = best->generation;
    b["genome"] = genome_to_json(genes_of(best->genome));
    json radius = json::array(), sensors = json::array();
    if (best->has_morphology)
      for (const auto& sp : best->morphology.spheres) {
        radius.push_back(num(sp.radius));
        sensors.push_back(sp.sensors);
      }
    b["radius"] = std::move(radius);
    b["sensors"] = std::move(sensors);
    const auto z = s.min_center_z.find(best->genome.genome_id);
    if (z == s.min_center_z.end()) {
      b["min_center_z"] = nullptr;
    } else {
      json zs = json::array();
      for (double x : z->second) zs.push_back(num(x));
      b["min_center_z"] = std::move(zs);
    }
    j["best"] = std::move(b);
  } else {
    j["best"] = nullptr;
  }
  return j;
}

RunResults run_results_from_json(const json& j, const std::string& path) {
  try {
    if (!j.is_object()) fail("results", "not a JSON object");
    if (as_string(field(j, "format", "results"), "results.format") != kRunResultsFormat)
      fail("results.format", std::string("not ") + kRunResultsFormat);
    const int64_t version = as_i64(field(j, "version", "results"), "results.version");
    if (version != kRunResultsVersion)
      fail("results.version",
           std::to_string(version) + " (this robozoo reads version " + std::to_string(kRunResultsVersion) + ")");
    RunResults res;
    RunSummary& s = res.run;
    const json& run = field(j, "run", "results");
    const std::string rp = "results.run";
    s.run_id = as_string(field(run, "run_id", rp), rp + ".run_id");
    const std::string log = as_string(field(run, "log", rp), rp + ".log");
    if (log.empty() || log.find('/') != std::string::npos || log == "." || log == "..")
      fail(rp + ".log", "must be a file name");
    s.path = (std::filesystem::path(path).parent_path() / log).string();
    s.software_version = as_string(field(run, "software_version", rp), rp + ".software_version");
    s.seed = as_i64(field(run, "seed", rp), rp + ".seed");
    s.regime = static_cast<int8_t>(as_int(field(run, "regime", rp), rp + ".regime", -128, 127));
    s.population = as_i32(field(run, "population", rp), rp + ".population");
    s.generations_requested = as_i32(field(run, "generations", rp), rp + ".generations");
    s.steps = as_i32(field(run, "steps", rp), rp + ".steps");
    s.dt = read_num(field(run, "dt", rp), rp + ".dt");
    const json& config = field(run, "config", rp);
    if (config.is_object())
      s.config_json = config.dump();
    else if (config.is_string())
      s.config_json = config.get<std::string>();
    else
      fail(rp + ".config", "neither an object nor a string");
    apply_run_configuration(s);
    // The arm is derived; a file that says otherwise was edited or is damaged.
    const std::string arm = as_string(field(run, "arm", rp), rp + ".arm");
    if (arm != s.arm) fail(rp + ".arm", "'" + arm + "', but its regime and configuration make it '" + s.arm + "'");
    s.max_d = read_num(field(j, "max_d", "results"), "results.max_d");
    s.undecodable =
        as_int(field(j, "undecodable", "results"), "results.undecodable", 0, std::numeric_limits<int64_t>::max());
    s.truncated = as_bool(field(j, "truncated", "results"), "results.truncated");
    const json& es = field(j, "evolve_seconds", "results");
    if (!es.is_null()) {
      res.has_evolve_seconds = true;
      res.evolve_seconds = read_num(es, "results.evolve_seconds");
    }

    const json& g = field(j, "generations", "results");
    const std::string gp = "results.generations";
    const json& gen = array_of(g, "generation", gp, static_cast<size_t>(-1));
    const size_t n = gen.size();
    const json& best_f = array_of(g, "best_fitness", gp, n);
    const json& mean_f = array_of(g, "mean_fitness", gp, n);
    const json& se_f = array_of(g, "stderr_fitness", gp, n);
    const json& bsf = array_of(g, "best_so_far_fitness", gp, n);
    const json& evals = array_of(g, "evaluations", gp, n);
    const json& champ = array_of(g, "champion_id", gp, n);
    const json& species = array_of(g, "num_species", gp, n);
    const json& thr = array_of(g, "compatibility_threshold", gp, n);
    const json& outc = array_of(g, "outcomes", gp, n);
    std::map<int32_t, int64_t> champion_of;  // generation -> champion id
    for (size_t i = 0; i < n; ++i) {
      GenerationRecord r;
      r.generation =
          static_cast<int32_t>(as_int(gen[i], at(gp + ".generation", i), 0, std::numeric_limits<int32_t>::max()));
      if (i > 0 && r.generation <= s.generations.back().generation)
        fail(at(gp + ".generation", i), "generations must increase");
      r.best_fitness = read_num(best_f[i], at(gp + ".best_fitness", i));
      r.mean_fitness = read_num(mean_f[i], at(gp + ".mean_fitness", i));
      r.stderr_fitness = read_num(se_f[i], at(gp + ".stderr_fitness", i));
      r.best_so_far_fitness = read_num(bsf[i], at(gp + ".best_so_far_fitness", i));
      r.evaluations = as_i64(evals[i], at(gp + ".evaluations", i));
      r.champion_id = as_i64(champ[i], at(gp + ".champion_id", i));
      r.num_species = as_i32(species[i], at(gp + ".num_species", i));
      r.compatibility_threshold = read_num(thr[i], at(gp + ".compatibility_threshold", i));
      const std::string op = at(gp + ".outcomes", i);
      const json& o = as_array(outc[i], op);
      if (o.size() != r.outcomes.size()) fail(op, "has " + std::to_string(o.size()) + " counts, expected 6");
      for (size_t k = 0; k < o.size(); ++k) r.outcomes[k] = as_i32(o[k], at(op, k));
      champion_of[r.generation] = r.champion_id;
      s.generations.push_back(r);
    }

    const json& champs = as_array(field(j, "champions", "results"), "results.champions");
    for (size_t i = 0; i < champs.size(); ++i) {
      const std::string cp = at("results.champions", i);
      const json& c = champs[i];
      ChampionRecord r;
      r.generation = as_i32(field(c, "generation", cp), cp + ".generation");
      const auto owner = champion_of.find(r.generation);
      if (owner == champion_of.end()) fail(cp + ".generation", "no such generation in results.generations");
      if (!s.champions.empty() && r.generation <= s.champions.back().generation)
        fail(cp + ".generation", "champions must be in increasing generation order");
      cppn_genome_t& m = r.genome;
      m.run_id = s.run_id;
      m.generation = r.generation;
      m.genome_id = as_i64(field(c, "genome_id", cp), cp + ".genome_id");
      if (m.genome_id != owner->second)
        fail(cp + ".genome_id", std::to_string(m.genome_id) + ", but generation " + std::to_string(r.generation) +
                                    "'s champion is " + std::to_string(owner->second));
      m.species_id = as_i32(field(c, "species_id", cp), cp + ".species_id");
      m.fitness = read_num(field(c, "fitness", cp), cp + ".fitness");
      m.r_term = read_num(field(c, "r_term", cp), cp + ".r_term");
      m.d_term = read_num(field(c, "d_term", cp), cp + ".d_term");
      m.outcome = static_cast<int8_t>(as_int(field(c, "outcome", cp), cp + ".outcome", -128, 127));
      const json& parents = field(c, "parents", cp);
      const json& joints = field(c, "joints", cp);
      if (!parents.is_null()) {
        const json& pa = as_array(parents, cp + ".parents");
        const std::string js = as_string(joints, cp + ".joints");
        if (pa.empty()) fail(cp + ".parents", "a robot has at least one sphere");
        if (js.size() != pa.size())
          fail(cp + ".joints",
               "has " + std::to_string(js.size()) + " flags for " + std::to_string(pa.size()) + " spheres");
        r.has_morphology = true;
        r.morphology.generation = r.generation;
        r.morphology.genome_id = m.genome_id;
        r.morphology.num_spheres = static_cast<int32_t>(pa.size());
        r.morphology.spheres.resize(pa.size());
        for (size_t k = 0; k < pa.size(); ++k) {
          sphere_t& sp = r.morphology.spheres[k];
          sp = sphere_t{};
          sp.index = static_cast<int32_t>(k);
          sp.motor_neuron = -1;
          const int64_t hi = static_cast<int64_t>(k) - 1;
          sp.parent = static_cast<int32_t>(k == 0 ? as_int(pa[k], at(cp + ".parents", k), -1, -1)
                                                  : as_int(pa[k], at(cp + ".parents", k), 0, hi));
          if (js[k] != '0' && js[k] != '1') fail(cp + ".joints", "flags must be '0' or '1'");
          sp.has_joint = js[k] == '1';
        }
      } else if (!joints.is_null()) {
        fail(cp + ".joints", "given without parents");
      }
      s.champions.push_back(std::move(r));
    }

    const json& best = field(j, "best", "results");
    const ChampionRecord* top = best_of_run(s);
    if (best.is_null() != (top == nullptr))
      fail("results.best", top ? "missing, but there are champions" : "given, but there is no champion");
    if (!best.is_null()) {
      const std::string bp = "results.best";
      const int32_t gen_b = as_i32(field(best, "generation", bp), bp + ".generation");
      if (gen_b != top->generation)
        fail(bp + ".generation", std::to_string(gen_b) + ", but the fittest champion is generation " +
                                     std::to_string(top->generation) + "'s");
      ChampionRecord& c = s.champions[static_cast<size_t>(top - s.champions.data())];
      // Structure only: any logged genome is kept (robozoo-evolve champion checks it against robozoo's layout).
      const Genome genome = genome_from_json(field(best, "genome", bp), bp + ".genome");
      if (genome.id != c.genome.genome_id)
        fail(bp + ".genome.id",
             std::to_string(genome.id) + ", but the champion is " + std::to_string(c.genome.genome_id));
      cppn_genome_t m = make_genome_message(s.run_id, c.generation, genome, c.genome.species_id, GenomeScore{}, 0);
      m.fitness = c.genome.fitness;
      m.r_term = c.genome.r_term;
      m.d_term = c.genome.d_term;
      m.outcome = c.genome.outcome;
      c.genome = std::move(m);
      const json& radius = as_array(field(best, "radius", bp), bp + ".radius");
      const json& sensors = as_array(field(best, "sensors", bp), bp + ".sensors");
      const size_t ns = c.has_morphology ? c.morphology.spheres.size() : 0;
      if (radius.size() != ns)
        fail(bp + ".radius",
             "has " + std::to_string(radius.size()) + " entries for " + std::to_string(ns) + " spheres");
      if (sensors.size() != ns)
        fail(bp + ".sensors",
             "has " + std::to_string(sensors.size()) + " entries for " + std::to_string(ns) + " spheres");
      for (size_t k = 0; k < ns; ++k) {
        c.morphology.spheres[k].radius = read_num(radius[k], at(bp + ".radius", k));
        c.morphology.spheres[k].sensors = static_cast<int8_t>(as_int(sensors[k], at(bp + ".sensors", k), -128, 127));
      }
      const json& z = field(best, "min_center_z", bp);
      if (!z.is_null()) {
        const json& za = as_array(z, bp + ".min_center_z");
        if (c.has_morphology && za.size() != ns)
          fail(bp + ".min_center_z",
               "has " + std::to_string(za.size()) + " heights for " + std::to_string(ns) + " spheres");
        std::vector<double> zs;
        for (size_t k = 0; k < za.size(); ++k) zs.push_back(read_num(za[k], at(bp + ".min_center_z", k)));
        s.min_center_z[c.genome.genome_id] = std::move(zs);
      }
    }
    return res;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(path + ": " + e.what());
  }
}

RunResults run_results_from_text(const std::string& text, const std::string& path) {
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded()) throw std::invalid_argument(path + ": not valid JSON (not a compact result?)");
  return run_results_from_json(j, path);
}

void write_run_results(const std::string& path, const RunResults& r) {
  write_file_atomic(path, run_results_to_json(r).dump() + "\n");
}

RunResults read_run_results(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read the compact result");
  std::stringstream ss;
  ss << in.rdbuf();
  if (!in.good() && !in.eof()) throw std::runtime_error(path + ": cannot read the compact result");
  return run_results_from_text(ss.str(), path);
}

}  // namespace robozoo
