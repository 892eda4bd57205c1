#include "evolve/neat/population_json.hpp"

#include "evolve/core/json_fields.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace robozoo {
namespace {

using nlohmann::json;
using namespace json_fields;

}  // namespace

std::string node_kind_name(NodeKind k) {
  switch (k) {
    case NodeKind::Input: return "input";
    case NodeKind::Bias: return "bias";
    case NodeKind::Output: return "output";
    case NodeKind::Hidden: return "hidden";
  }
  return "unknown";
}

NodeKind node_kind_from_name(const std::string& name) {
  for (NodeKind k : {NodeKind::Input, NodeKind::Bias, NodeKind::Output, NodeKind::Hidden})
    if (node_kind_name(k) == name) return k;
  throw std::invalid_argument("unknown node kind '" + name + "' (input, bias, output, hidden)");
}

json genome_to_json(const Genome& g) {
  json nodes = json::array();
  for (const auto& n : g.nodes)
    nodes.push_back({{"id", n.id},
                     {"kind", node_kind_name(n.kind)},
                     {"activation", activation_name(n.activation)},
                     {"position", n.position}});
  json links = json::array();
  for (const auto& l : g.links)
    links.push_back({{"innovation", l.innovation},
                     {"from", l.from},
                     {"to", l.to},
                     {"weight", l.weight},
                     {"enabled", l.enabled},
                     {"born", l.born}});
  return {{"id", g.id}, {"nodes", std::move(nodes)}, {"links", std::move(links)}};
}

Genome genome_from_json(const json& j, const std::string& path) {
  Genome g;
  g.id = as_i64(field(j, "id", path), path + ".id");
  const std::string np = path + ".nodes";
  const json& nodes = as_array(field(j, "nodes", path), np);
  for (size_t i = 0; i < nodes.size(); ++i) {
    const std::string p = at(np, i);
    NodeGene n;
    n.id = as_i32(field(nodes[i], "id", p), p + ".id");
    try {
      n.kind = node_kind_from_name(as_string(field(nodes[i], "kind", p), p + ".kind"));
      n.activation = activation_from_name(as_string(field(nodes[i], "activation", p), p + ".activation"));
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      if (what.rfind(p, 0) == 0) throw;  // already names its path
      fail(p, what);
    }
    // Inputs and outputs sit at 0 and 1; a hidden node's position must be given
    // (genomes written before drawing positions existed have none).
    if (nodes[i].contains("position"))
      n.position = as_double(nodes[i]["position"], p + ".position");
    else if (n.kind == NodeKind::Hidden)
      fail(p, "hidden node " + std::to_string(n.id) +
                  " has no \"position\" (drawing position; genomes written before robozoo used "
                  "HyperNEAT's positions lack it)");
    else
      n.position = n.kind == NodeKind::Output ? kOutputPosition : kInputPosition;
    g.nodes.push_back(n);
  }
  const std::string lp = path + ".links";
  const json& links = as_array(field(j, "links", path), lp);
  for (size_t i = 0; i < links.size(); ++i) {
    const std::string p = at(lp, i);
    LinkGene l;
    l.innovation = as_i64(field(links[i], "innovation", p), p + ".innovation");
    l.from = as_i32(field(links[i], "from", p), p + ".from");
    l.to = as_i32(field(links[i], "to", p), p + ".to");
    l.weight = as_double(field(links[i], "weight", p), p + ".weight");
    l.enabled = as_bool(field(links[i], "enabled", p), p + ".enabled");
    l.born = as_i32(field(links[i], "born", p), p + ".born");
    g.links.push_back(l);
  }
  return g;
}

json species_to_json(const Species& s) {
  return {{"id", s.id},
          {"age", s.age},
          {"last_improvement", s.last_improvement},
          {"best_fitness", s.best_fitness},
          {"representative", genome_to_json(s.representative)},
          {"members", s.members}};
}

Species species_from_json(const json& j, const std::string& path) {
  Species s;
  s.id = as_i32(field(j, "id", path), path + ".id");
  s.age = as_i32(field(j, "age", path), path + ".age");
  s.last_improvement = as_i32(field(j, "last_improvement", path), path + ".last_improvement");
  s.best_fitness = as_double(field(j, "best_fitness", path), path + ".best_fitness");
  s.representative = genome_from_json(field(j, "representative", path), path + ".representative");
  const std::string mp = path + ".members";
  const json& members = as_array(field(j, "members", path), mp);
  for (size_t i = 0; i < members.size(); ++i) s.members.push_back(as_i32(members[i], at(mp, i)));
  return s;
}

json population_state_to_json(const PopulationState& s) {
  json genomes = json::array();
  for (const auto& g : s.genomes) genomes.push_back(genome_to_json(g));
  json species = json::array();
  for (const auto& sp : s.species) species.push_back(species_to_json(sp));
  json j = {{"generation", s.generation},
            {"next_genome_id", s.next_genome_id},
            {"next_innovation", s.next_innovation},
            {"next_node_id", s.next_node_id},
            {"next_species_id", s.next_species_id},
            {"compatibility_threshold", s.compatibility_threshold},
            {"speciation_threshold", s.speciation_threshold},
            {"genomes", std::move(genomes)},
            {"species_of", s.species_of},
            {"species", std::move(species)}};
  // Population-level stagnation's record, written only when it is in use (non-zero), so states
  // of runs without it read and write as before.
  if (s.record_fitness != 0.0 || s.generations_since_record != 0) {
    j["record_fitness"] = s.record_fitness;
    j["generations_since_record"] = s.generations_since_record;
  }
  return j;
}

PopulationState population_state_from_json(const json& j, const std::string& path) {
  PopulationState s;
  s.generation = as_i32(field(j, "generation", path), path + ".generation");
  s.next_genome_id = as_i64(field(j, "next_genome_id", path), path + ".next_genome_id");
  s.next_innovation = as_i64(field(j, "next_innovation", path), path + ".next_innovation");
  s.next_node_id = as_i32(field(j, "next_node_id", path), path + ".next_node_id");
  s.next_species_id = as_i32(field(j, "next_species_id", path), path + ".next_species_id");
  s.compatibility_threshold = as_double(field(j, "compatibility_threshold", path), path + ".compatibility_threshold");
  s.speciation_threshold = as_double(field(j, "speciation_threshold", path), path + ".speciation_threshold");
  const std::string gp = path + ".genomes";
  const json& genomes = as_array(field(j, "genomes", path), gp);
  for (size_t i = 0; i < genomes.size(); ++i) s.genomes.push_back(genome_from_json(genomes[i], at(gp, i)));
  const std::string op = path + ".species_of";
  const json& species_of = as_array(field(j, "species_of", path), op);
  for (size_t i = 0; i < species_of.size(); ++i) s.species_of.push_back(as_i32(species_of[i], at(op, i)));
  const std::string sp = path + ".species";
  const json& species = as_array(field(j, "species", path), sp);
  for (size_t i = 0; i < species.size(); ++i) s.species.push_back(species_from_json(species[i], at(sp, i)));
  if (j.contains("record_fitness")) s.record_fitness = as_double(j["record_fitness"], path + ".record_fitness");
  if (j.contains("generations_since_record"))
    s.generations_since_record = as_i32(j["generations_since_record"], path + ".generations_since_record");
  return s;
}

void to_json(json& j, const Genome& g) { j = genome_to_json(g); }
void from_json(const json& j, Genome& g) { g = genome_from_json(j); }
void to_json(json& j, const Species& s) { j = species_to_json(s); }
void from_json(const json& j, Species& s) { s = species_from_json(j); }
void to_json(json& j, const PopulationState& s) { j = population_state_to_json(s); }
void from_json(const json& j, PopulationState& s) { s = population_state_from_json(j); }

}  // namespace robozoo
