#pragma once
// JSON for genome files and checkpoints: Genome, Species, PopulationState.
//
// Doubles are written as JSON numbers: nlohmann-json prints the shortest text
// that parses back to the same double, so weights and fitnesses round-trip bit
// for bit (tested). Node kinds and activations are written by name
// ("input", "bias", "output", "hidden"; activation_name()).
//
// Reading checks structure only (keys present, types right, values in the
// range of their C++ type) and throws std::invalid_argument naming the path of
// the first problem, e.g. "genome.links[3].weight: missing". Semantic checks
// (validate_genome, the Population state constructor) are the caller's.
#include <nlohmann/json.hpp>

#include "evolve/cppn/genome.hpp"
#include "evolve/neat/population.hpp"
#include "evolve/neat/species/species.hpp"

namespace robozoo {

nlohmann::json genome_to_json(const Genome& g);
/// `path` prefixes error messages.
Genome genome_from_json(const nlohmann::json& j, const std::string& path = "genome");

nlohmann::json species_to_json(const Species& s);
Species species_from_json(const nlohmann::json& j, const std::string& path = "species");

nlohmann::json population_state_to_json(const PopulationState& s);
PopulationState population_state_from_json(const nlohmann::json& j, const std::string& path = "population");

std::string node_kind_name(NodeKind k);                 ///< "input", "bias", "output", "hidden"
NodeKind node_kind_from_name(const std::string& name);  ///< throws std::invalid_argument

// nlohmann-json's ADL hooks (j = genome; j.get<Genome>()), same formats.
void to_json(nlohmann::json& j, const Genome& g);
void from_json(const nlohmann::json& j, Genome& g);
void to_json(nlohmann::json& j, const Species& s);
void from_json(const nlohmann::json& j, Species& s);
void to_json(nlohmann::json& j, const PopulationState& s);
void from_json(const nlohmann::json& j, PopulationState& s);

}  // namespace robozoo
