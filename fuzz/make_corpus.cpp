// robozoo-fuzz-corpus: cuts a real run into seed corpora for the fuzz targets.
//
//   robozoo-fuzz-corpus LOG CHECKPOINT CONFIG_JSON OUT
//
// writes OUT/<target>/ for every target in fuzz/: a few messages of each
// channel (and eval_result_t built from the logged genomes' results, bus_status_t
// from the logged generations), a short
// log of the run's first events, the configuration as JSON and as TOML, the
// logged champions' genomes as genome JSON, the checkpoint, and the run as a
// portable checkpoint. Seeds are kept small: libFuzzer's longest input defaults
// to the longest seed.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include <toml++/toml.h>

#include "evolve/record/run_results.hpp"
#include "evolve/io/event_log.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/neat/population_json.hpp"
#include "robozoo/eval_result_t.hpp"
#include "study/analysis/read/log_results.hpp"
#include "study/experiment/portable_checkpoint.hpp"

namespace fs = std::filesystem;
using namespace robozoo;

namespace {

void write_file(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream out(p, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error(p.string() + ": cannot write");
}
void write_bytes(const fs::path& p, const std::vector<uint8_t>& b) { write_file(p, std::string(b.begin(), b.end())); }
std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error(p.string() + ": cannot read");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// JSON to TOML (objects become tables): the configuration's own keys only hold
// numbers, booleans, strings, arrays and objects.
toml::table to_toml(const nlohmann::json& j);
toml::array to_toml_array(const nlohmann::json& j);
template <class Add>
void add_value(const nlohmann::json& v, Add add) {
  if (v.is_object())
    add(to_toml(v));
  else if (v.is_array())
    add(to_toml_array(v));
  else if (v.is_boolean())
    add(v.get<bool>());
  else if (v.is_number_integer())
    add(v.get<int64_t>());
  else if (v.is_number())
    add(v.get<double>());
  else if (v.is_string())
    add(v.get<std::string>());
}
toml::table to_toml(const nlohmann::json& j) {
  toml::table t;
  for (const auto& item : j.items()) {
    const std::string key = item.key();
    add_value(item.value(), [&](auto&& x) { t.insert(key, std::forward<decltype(x)>(x)); });
  }
  return t;
}
toml::array to_toml_array(const nlohmann::json& j) {
  toml::array a;
  for (const auto& v : j) add_value(v, [&](auto&& x) { a.push_back(std::forward<decltype(x)>(x)); });
  return a;
}

// An event log of `records` in LCM's format.
std::vector<uint8_t> log_bytes(const std::vector<LogRecord>& records) {
  std::vector<uint8_t> out;
  auto be = [&](uint64_t v, int n) {
    for (int i = n - 1; i >= 0; --i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
  };
  for (const auto& r : records) {
    be(0xEDA1DA01u, 4);
    be(static_cast<uint64_t>(r.eventnum), 8);
    be(static_cast<uint64_t>(r.timestamp), 8);
    be(r.channel.size(), 4);
    be(r.data.size(), 4);
    out.insert(out.end(), r.channel.begin(), r.channel.end());
    out.insert(out.end(), r.data.begin(), r.data.end());
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5 || std::string(argv[1]) == "--help") {
    std::cerr << "usage: robozoo-fuzz-corpus LOG CHECKPOINT CONFIG_JSON OUT\n"
                 "Cuts a real run (its log, checkpoint and --print-config output) into seed corpora,\n"
                 "one folder per fuzz target in OUT.\n";
    return argc == 2 ? 0 : 2;
  }
  try {
    const fs::path out = argv[4];
    const LogContents log = read_event_log(argv[1]);
    if (log.records.empty() || log.truncated) throw std::runtime_error(std::string(argv[1]) + ": empty or damaged log");
    const std::map<std::string, std::string> folder = {{kChannelRun, "run_t"},
                                                       {kChannelGeneration, "generation_t"},
                                                       {kChannelGenome, "cppn_genome_t"},
                                                       {kChannelMorphology, "morphology_t"},
                                                       {kChannelPose, "pose_t"}};
    std::map<std::string, int> written;
    const int per_channel = 4;
    std::vector<LogRecord> head;  // the run's first events, up to its first few poses
    int head_poses = 0;
    for (const auto& r : log.records) {
      auto f = folder.find(r.channel);
      if (f == folder.end()) continue;
      if (head_poses < 3) {
        head.push_back(r);
        head_poses += r.channel == kChannelPose;
      }
      int& n = written[r.channel];
      if (n >= per_channel) continue;
      write_bytes(out / f->second / (std::to_string(n) + ".bin"), r.data);
      ++n;
      if (r.channel == kChannelGenome) {
        cppn_genome_t m;
        if (!safe_decode(r.data.data(), r.data.size(), m)) throw std::runtime_error("a logged genome does not decode");
        eval_result_t e{};
        e.genome_id = m.genome_id;
        e.fitness = m.fitness;
        e.r_term = m.r_term;
        e.d_term = m.d_term;
        e.outcome = m.outcome;
        e.num_spheres = 3;
        e.num_bodies = 2;
        e.num_joints = 1;
        e.num_sensors = 2;
        e.steps_run = 100;
        write_bytes(out / "eval_result_t" / (std::to_string(n) + ".bin"), encode_message(e));
        nlohmann::json g = genome_to_json(genome_from_message(m, robot_layout()));
        if (n > 1) g["links"].erase(g["links"].begin() + std::min<size_t>(5, g["links"].size()), g["links"].end());
        write_file(out / "genome_json" / (std::to_string(n) + ".json"), g.dump() + "\n");
      }
      if (r.channel == kChannelGeneration) {
        // bus_status_t is never logged: made from the run's own generation messages,
        // as robozoo-evolve sends it after each generation.
        generation_t m;
        if (!safe_decode(r.data.data(), r.data.size(), m))
          throw std::runtime_error("a logged generation_t does not decode");
        bus_status_t b{};
        b.utime = m.utime;
        b.run_id = m.run_id;
        b.generation = m.generation;
        b.messages_published = 5 * (m.generation + 1);
        b.bytes_published = 4096 * (m.generation + 1);
        b.publish_failures = n - 1;
        write_bytes(out / "bus_status_t" / (std::to_string(n) + ".bin"), encode_message(b));
      }
      if (r.channel == kChannelRun) {
        run_t m;
        if (!safe_decode(r.data.data(), r.data.size(), m)) throw std::runtime_error("a logged run_t does not decode");
        write_file(out / "config_json" / "run_t.json", m.config_json);
      }
    }
    // The run's compact result, its best genome cut to 5 link genes (the whole one is 20 kB).
    nlohmann::json results = run_results_to_json(results_from_log(argv[1]));
    if (results["best"].is_object()) {
      auto& links = results["best"]["genome"]["links"];
      links.erase(links.begin() + std::min<size_t>(5, links.size()), links.end());
    }
    write_file(out / "run_results" / "run.results.json", results.dump() + "\n");
    write_bytes(out / "event_log" / "head.lcmlog", log_bytes(head));
    write_bytes(out / "event_log" / "first.lcmlog", log_bytes({head.front()}));
    const std::string config = read_file(argv[3]);
    write_file(out / "config_json" / "config.json", config);
    std::ostringstream toml_text;
    toml_text << to_toml(nlohmann::json::parse(config)) << "\n";
    write_file(out / "config_toml" / "config.toml", toml_text.str());
    // The checkpoint cut down to 4 genomes of at most 3 links each (a whole one
    // is hundreds of kB, which would slow every execution).
    nlohmann::json cp = nlohmann::json::parse(read_file(argv[2]));
    auto& pop = cp.at("population");
    auto cut_links = [](nlohmann::json& g) {
      auto& links = g.at("links");
      links.erase(links.begin() + std::min<size_t>(3, links.size()), links.end());
    };
    auto& genomes = pop.at("genomes");
    genomes.erase(genomes.begin() + std::min<size_t>(4, genomes.size()), genomes.end());
    for (auto& g : genomes) cut_links(g);
    auto& species_of = pop.at("species_of");
    species_of.erase(species_of.begin() + std::min<size_t>(4, species_of.size()), species_of.end());
    for (auto& sp : pop.at("species")) cut_links(sp.at("representative"));
    write_file(out / "checkpoint" / "checkpoint.json", cp.dump() + "\n");
    // The run as a portable checkpoint (its checkpoint and compact result, compressed): without a
    // valid one to mutate, the fuzzer would hardly get past the format's checksums.
    write_bytes(out / "portable_checkpoint" / "run.portable-checkpoint",
                encode_portable_checkpoint(pack_portable_checkpoint(argv[1])));
    std::cout << "robozoo-fuzz-corpus: seeds in " << out.string() << " from " << log.records.size() << " events\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "robozoo-fuzz-corpus: " << e.what() << "\n";
    return 1;
  }
}
