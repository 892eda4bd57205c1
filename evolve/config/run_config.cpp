#include "evolve/config/run_config.hpp"

#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "evolve/config/field_table.hpp"

namespace robozoo {

void throw_config_error(const std::string& message) { throw ConfigError(message); }

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr long long kBig = 1000000000LL;

FieldTable<NeatParams> neat_table() {
  FieldTable<NeatParams> t("neat");
  t.integer("population", &NeatParams::population, 2, kBig)
      .real("disjoint_coefficient", &NeatParams::disjoint_coefficient, 0, kInf)
      .real("excess_coefficient", &NeatParams::excess_coefficient, 0, kInf)
      .real("weight_coefficient", &NeatParams::weight_coefficient, 0, kInf)
      .real("compatibility_threshold", &NeatParams::compatibility_threshold, 0, kInf, true)
      .real("compatibility_modifier", &NeatParams::compatibility_modifier, 0, kInf)
      .real("min_compatibility_threshold", &NeatParams::min_compatibility_threshold, 0, kInf, true)
      .integer("target_species", &NeatParams::target_species, 1, kBig)
      .real("survival_threshold", &NeatParams::survival_threshold, 0, 1, true)
      .integer("dropoff_age", &NeatParams::dropoff_age, 1, kBig)
      .real("dropoff_factor", &NeatParams::dropoff_factor, 0, 1)
      .real("add_node_probability", &NeatParams::add_node_probability, 0, 1)
      .real("add_link_probability", &NeatParams::add_link_probability, 0, 1)
      .real("mutate_weights_probability", &NeatParams::mutate_weights_probability, 0, 1)
      .integer("young_link_age", &NeatParams::young_link_age, 0, kBig)
      .real("old_link_perturb_probability", &NeatParams::old_link_perturb_probability, 0, 1)
      .real("weight_perturbation", &NeatParams::weight_perturbation, 0, kInf)
      .real("weight_limit", &NeatParams::weight_limit, 0, kInf, true)
      .real("initial_weight_range", &NeatParams::initial_weight_range, 0, kInf)
      .real("mutate_only_probability", &NeatParams::mutate_only_probability, 0, 1)
      .real("interspecies_mating_probability", &NeatParams::interspecies_mating_probability, 0, 1)
      .integer("species_elitism_min_offspring", &NeatParams::species_elitism_min_offspring, 1, kBig)
      .integer("add_link_tries", &NeatParams::add_link_tries, 1, kBig)
      .choice("link_rule", &NeatParams::link_rule, link_rule_name, link_rule_from_name)
      .boolean("self_loops", &NeatParams::self_loops)
      .choice("initial_links", &NeatParams::initial_links, initial_links_name, initial_links_from_name)
      .choice("add_link", &NeatParams::add_link, add_link_rule_name, add_link_rule_from_name)
      .choice("add_node", &NeatParams::add_node, add_node_rule_name, add_node_rule_from_name)
      .choice("add_node_innovations", &NeatParams::add_node_innovations, add_node_innovations_name,
              add_node_innovations_from_name)
      .choice("compatibility", &NeatParams::compatibility, compatibility_rule_name, compatibility_rule_from_name)
      .real("disabled_gene_probability", &NeatParams::disabled_gene_probability, 0, 1)
      .choice("weight_mutation", &NeatParams::weight_mutation, weight_mutation_rule_name,
              weight_mutation_rule_from_name)
      .real("weight_replace_probability", &NeatParams::weight_replace_probability, 0, 1)
      .real("mate_average_probability", &NeatParams::mate_average_probability, 0, 1)
      .real("mate_only_probability", &NeatParams::mate_only_probability, 0, 1)
      .choice("crossover_rule", &NeatParams::crossover_rule, crossover_rule_name, crossover_rule_from_name)
      .boolean("independent_parents", &NeatParams::independent_parents)
      .boolean("keep_generation_champion", &NeatParams::keep_generation_champion)
      .choice("stagnation", &NeatParams::stagnation, stagnation_rule_name, stagnation_rule_from_name)
      .choice("offspring_rounding", &NeatParams::offspring_rounding, offspring_rounding_name,
              offspring_rounding_from_name)
      .integer("population_stagnation_generations", &NeatParams::population_stagnation_generations, 0, kBig)
      .boolean("split_bias_links", &NeatParams::split_bias_links)
      .boolean("structural_draw_decides", &NeatParams::structural_draw_decides)
      .boolean("childless_species_stay", &NeatParams::childless_species_stay)
      .choice("crossover_genes", &NeatParams::crossover_genes, crossover_genes_name, crossover_genes_from_name)
      .choice("mutation_order", &NeatParams::mutation_order, mutation_order_name, mutation_order_from_name)
      .choice("representative", &NeatParams::representative, representative_name, representative_from_name)
      .choice("threshold_rule", &NeatParams::threshold_rule, threshold_rule_name, threshold_rule_from_name)
      // A named set of mechanics: written as the set the others match ("custom" when none); read
      // first (read_neat), so that keys given beside it override it.
      .custom(
          "mechanics", [](const NeatParams& p) { return nlohmann::json(neat_mechanics_of(p)); },
          [](NeatParams& p, const nlohmann::json& v, const std::string& q) {
            if (!v.is_string()) throw_config_error(q + ": must be a name, got " + shown(v));
            if (v.get<std::string>() == "custom") return;  // the other keys say what they are
            try {
              apply_neat_mechanics(p, neat_mechanics_from_name(v.get<std::string>()));
            } catch (const std::invalid_argument& e) {
              throw_config_error(q + ": " + std::string(e.what()) + " or custom");
            }
          })
      .custom(
          "hidden_activations",
          [](const NeatParams& p) {
            nlohmann::json a = nlohmann::json::array();
            for (int c = 0; c < kNumActivations; ++c)
              if (p.hidden_activations & (1u << c)) a.push_back(activation_name(static_cast<Activation>(c)));
            return a;
          },
          [](NeatParams& p, const nlohmann::json& v, const std::string& q) {
            if (!v.is_array() || v.empty())
              throw_config_error(q + ": must be a non-empty list of activation names, got " + shown(v));
            uint32_t mask = 0;
            for (const auto& e : v) {
              if (!e.is_string()) throw_config_error(q + ": must list names, got " + shown(e));
              try {
                mask |= 1u << static_cast<int>(activation_from_name(e.get<std::string>()));
              } catch (const std::invalid_argument& err) {
                throw_config_error(q + ": " + err.what());
              }
            }
            p.hidden_activations = mask;
          });
  return t;
}

// neat.mechanics first, then every other key (which may override part of the set).
void read_neat(NeatParams& p, const nlohmann::json& v) {
  const FieldTable<NeatParams> t = neat_table();
  if (!v.is_object() || !v.contains("mechanics")) return t.read(p, v);
  t.read(p, nlohmann::json{{"mechanics", v.at("mechanics")}});
  nlohmann::json rest = v;
  rest.erase("mechanics");
  t.read(p, rest);
}

FieldTable<GrowthParams> growth_table() {
  FieldTable<GrowthParams> t("growth");
  t.real("r_init", &GrowthParams::r_init, 0, kInf, true)
      .real("r_min", &GrowthParams::r_min, 0, kInf, true)
      .real("r_max", &GrowthParams::r_max, 0, kInf, true)
      .real("t_matter", &GrowthParams::t_matter, -1, 1, false, true)
      .real("t_joint", &GrowthParams::t_joint, -1, 1, false, true)
      .real("t_sensor", &GrowthParams::t_sensor, -1, 1)
      .real("weight_threshold", &GrowthParams::weight_threshold, 0, 1)
      .real("rho_min", &GrowthParams::rho_min, 0, kInf, true)
      .real("rho_max", &GrowthParams::rho_max, 0, kInf, true)
      .real("max_joint_range", &GrowthParams::max_joint_range, 0, M_PI)
      .real("tau_min", &GrowthParams::tau_min, 0, kInf, true)
      .real("tau_max", &GrowthParams::tau_max, 0, kInf, true)
      .real("bias_max", &GrowthParams::bias_max, 0, kInf)
      .real("weight_max", &GrowthParams::weight_max, 0, kInf)
      .choice("weight_mapping", &GrowthParams::weight_mapping, weight_mapping_name, weight_mapping_from_name)
      .real("bias_input", &GrowthParams::bias_input, -kInf, kInf)
      .integer("cloud_points", &GrowthParams::cloud_points, 1, 100000)
      .real("cloud_step", &GrowthParams::cloud_step, 0, 2 * M_PI, true)
      .real("bound", &GrowthParams::bound, 0, kInf, true)
      .integer("max_spheres", &GrowthParams::max_spheres, 1, 10000)
      .real("touch_tolerance", &GrowthParams::touch_tolerance, 0, 1e-3, false, true);
  return t;
}

FieldTable<SimParams> sim_table() {
  FieldTable<SimParams> t("sim");
  t.integer("steps", &SimParams::steps, 1, kBig)
      .real("dt", &SimParams::dt, 0, 1, true)
      .real("gravity", &SimParams::gravity, 0, kInf)
      .integer("ode_seed", &SimParams::ode_seed, 0, 4294967295LL)
      .integer("quickstep_iterations", &SimParams::quickstep_iterations, 1, 10000)
      .real("erp", &SimParams::erp, 0, 1)
      .real("cfm", &SimParams::cfm, 0, kInf)
      .real("contact_erp", &SimParams::contact_erp, 0, 1)
      .real("contact_cfm", &SimParams::contact_cfm, 0, kInf)
      .real("friction", &SimParams::friction, 0, kInf)
      .integer("max_contacts", &SimParams::max_contacts, 1, 64)
      .real("servo_gain", &SimParams::servo_gain, 0, kInf)
      .real("servo_max_speed", &SimParams::servo_max_speed, 0, kInf)
      .real("max_correcting_velocity", &SimParams::max_correcting_velocity, 0, kInf)
      .real("motor_strength", &SimParams::motor_strength, 0, kInf)
      .real("target_x", &SimParams::target_x, -kInf, kInf)
      .real("target_y", &SimParams::target_y, -kInf, kInf)
      .real("target_z", &SimParams::target_z, -kInf, kInf)
      .real("distance_sensor_range", &SimParams::distance_sensor_range, 0, kInf, true)
      .real("time_sensor_frequency", &SimParams::time_sensor_frequency, 0, kInf)
      .real("rest_linear_speed", &SimParams::rest_linear_speed, 0, kInf)
      .real("rest_angular_speed", &SimParams::rest_angular_speed, 0, kInf)
      .real("rest_output_rate", &SimParams::rest_output_rate, 0, kInf)
      .integer("rest_steps", &SimParams::rest_steps, 1, kBig)
      .real("max_linear_acceleration", &SimParams::max_linear_acceleration, 0, kInf, true)
      .real("max_angular_acceleration", &SimParams::max_angular_acceleration, 0, kInf, true)
      .boolean("rolling_contact_rule", &SimParams::rolling_contact_rule)
      .real("rolling_contact_fraction", &SimParams::rolling_contact_fraction, 0, 1)
      .boolean("rolling_spin_rule", &SimParams::rolling_spin_rule)
      .real("rolling_spin_threshold", &SimParams::rolling_spin_threshold, 0, kInf);
  return t;
}

FieldTable<RunConfig> top_table() {
  FieldTable<RunConfig> t("");
  t.custom(
       "regime", [](const RunConfig& c) { return nlohmann::json(regime_name(c.regime)); },
       [](RunConfig& c, const nlohmann::json& v, const std::string& q) {
         if (!v.is_string()) throw_config_error(q + ": must be \"feedforward\" or \"recurrent\", got " + shown(v));
         try {
           c.regime = regime_from_name(v.get<std::string>());
         } catch (const ConfigError& e) {
           throw_config_error(q + ": " + e.what());
         }
       })
      .integer("seed", &RunConfig::seed, std::numeric_limits<long long>::min(), std::numeric_limits<long long>::max())
      .integer("generations", &RunConfig::generations, 1, kBig)
      .integer("pose_every", &RunConfig::pose_every, 1, kBig)
      .boolean("publish_all", &RunConfig::publish_all)
      .custom(
          "cppn_updates", [](const RunConfig& c) { return nlohmann::json(c.eval.cppn_updates); },
          [](RunConfig& c, const nlohmann::json& v, const std::string& q) {
            if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 1000)
              throw_config_error(q + ": must be an integer in [1, 1000], got " + shown(v));
            c.eval.cppn_updates = v.get<int>();
          })
      .custom(
          "neat", [](const RunConfig& c) { return neat_table().write(c.neat); },
          [](RunConfig& c, const nlohmann::json& v, const std::string&) { read_neat(c.neat, v); })
      .custom(
          "growth", [](const RunConfig& c) { return growth_table().write(c.eval.growth); },
          [](RunConfig& c, const nlohmann::json& v, const std::string&) { growth_table().read(c.eval.growth, v); })
      .custom(
          "sim", [](const RunConfig& c) { return sim_table().write(c.eval.sim); },
          [](RunConfig& c, const nlohmann::json& v, const std::string&) { sim_table().read(c.eval.sim, v); });
  return t;
}

nlohmann::json toml_to_json(const toml::node& n, const std::string& where) {
  if (auto t = n.as_table()) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [k, v] : *t) j[std::string(k.str())] = toml_to_json(v, where);
    return j;
  }
  if (auto a = n.as_array()) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& v : *a) j.push_back(toml_to_json(v, where));
    return j;
  }
  if (auto v = n.as_integer()) return v->get();
  if (auto v = n.as_floating_point()) return v->get();
  if (auto v = n.as_boolean()) return v->get();
  if (auto v = n.as_string()) return v->get();
  throw ConfigError(where + ": dates and times are not configuration values");
}

}  // namespace

std::string regime_name(Regime r) { return r == Regime::Recurrent ? "recurrent" : "feedforward"; }

Regime regime_from_name(const std::string& s) {
  if (s == "feedforward" || s == "feed-forward" || s == "control") return Regime::FeedForward;
  if (s == "recurrent" || s == "experimental") return Regime::Recurrent;
  throw ConfigError("unknown regime '" + s + "' (use feedforward or recurrent)");
}

nlohmann::json config_to_json(const RunConfig& c) { return top_table().write(c); }

nlohmann::json config_assignment(const std::string& assignment) {
  const size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw ConfigError("--set " + assignment + ": expected KEY=VALUE, e.g. neat.initial_links=inputs_to_outputs");
  const std::string key = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  nlohmann::json value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) value = text;  // a bare name
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    const size_t dot = key.find('.', start);
    parts.push_back(key.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (parts.back().empty()) throw ConfigError("--set " + assignment + ": empty part in the key " + key);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  nlohmann::json j = value;
  for (auto it = parts.rbegin(); it != parts.rend(); ++it) j = nlohmann::json{{*it, j}};
  return j;
}

RunConfig config_from_json(const nlohmann::json& j, RunConfig base) {
  top_table().read(base, j);
  validate_config(base);
  return base;
}

RunConfig config_from_record(const nlohmann::json& j) {
  RunConfig base;
  const auto has = [&j](const char* section, const char* key) {
    return j.is_object() && j.contains(section) && j.at(section).is_object() && j.at(section).contains(key);
  };
  if (!has("growth", "bias_input")) base.eval.growth.bias_input = 1.0;
  if (!has("growth", "weight_mapping")) base.eval.growth.weight_mapping = WeightMapping::Proportional;
  if (!has("neat", "add_node_innovations")) base.neat.add_node_innovations = AddNodeInnovations::Shared;
  return config_from_json(j, base);
}

void validate_config(const RunConfig& c) {
  const auto& g = c.eval.growth;
  if (!(g.r_min <= g.r_max)) throw ConfigError("growth.r_min: must not exceed growth.r_max");
  if (!(g.r_min <= g.r_init && g.r_init <= g.r_max))
    throw ConfigError("growth.r_init: must lie in [growth.r_min, growth.r_max]");
  if (!(g.rho_min <= g.rho_max)) throw ConfigError("growth.rho_min: must not exceed growth.rho_max");
  if (!(g.tau_min <= g.tau_max)) throw ConfigError("growth.tau_min: must not exceed growth.tau_max");
  if (!(c.eval.sim.dt < g.tau_min))
    throw ConfigError("growth.tau_min: must exceed sim.dt, or explicit Euler of the CTRNN is unstable");
  if (!(c.neat.min_compatibility_threshold <= c.neat.compatibility_threshold))
    throw ConfigError("neat.min_compatibility_threshold: must not exceed neat.compatibility_threshold");
}

RunConfig config_from_text(const std::string& text, ConfigFormat format, const std::string& name, RunConfig base) {
  nlohmann::json j;
  if (format == ConfigFormat::Toml) {
    try {
      j = toml_to_json(toml::parse(text, name), name);
    } catch (const toml::parse_error& e) {
      std::ostringstream os;
      os << name << ":" << e.source().begin.line << ": " << e.description();
      throw ConfigError(os.str());
    }
  } else {
    try {
      j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {  // parse errors, and numbers beyond a double (out_of_range)
      throw ConfigError(name + ": not valid JSON (" + e.what() + ")");
    }
  }
  try {
    return config_from_json(j, base);
  } catch (const ConfigError& e) {
    throw ConfigError(name + ": " + e.what());
  }
}

RunConfig load_config_file(const std::string& path, RunConfig base) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path + ": cannot read configuration file");
  std::stringstream ss;
  ss << in.rdbuf();
  const bool is_toml = path.size() >= 5 && path.compare(path.size() - 5, 5, ".toml") == 0;
  return config_from_text(ss.str(), is_toml ? ConfigFormat::Toml : ConfigFormat::Json, path, base);
}

}  // namespace robozoo
