#include "replay/check/check_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "evolve/messages/build.hpp"

namespace robozoo::replay {

namespace {

std::string error_text(double e) {
  if (std::isinf(e)) return "exact field";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", e);
  return buf;
}

std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string where(const Mismatch& m) {
  std::string s = m.what;
  if (m.step >= 0) s += " step " + std::to_string(m.step);
  if (!m.element.empty()) s += " " + m.element;
  return s + " " + m.field;
}

nlohmann::json error_json(double e) { return std::isfinite(e) ? nlohmann::json(e) : nlohmann::json(nullptr); }

std::string plural(int64_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

int64_t CheckReport::count(ChampionResult::Status s) const {
  int64_t n = 0;
  for (const auto& c : champions) n += c.status == s;
  return n;
}

int CheckReport::exit_code() const {
  if (!fatal.empty()) return 2;
  if (count(ChampionResult::Status::Diverged) > 0 || !structure.empty()) return 1;
  if (count(ChampionResult::Status::Unusable) > 0 || !input_problems.empty()) return 2;
  return 0;
}

std::string champion_line(const ChampionResult& c, bool with_run) {
  std::ostringstream o;
  char head[64];
  std::snprintf(head, sizeof head, "%-9s",
                c.status == ChampionResult::Status::Ok         ? "ok"
                : c.status == ChampionResult::Status::Diverged ? "DIVERGED"
                                                               : "UNUSABLE");
  o << head;
  if (with_run) o << "run " << c.run_id << "  ";
  o << "gen " << c.generation << "  genome " << c.genome_id << (c.champion ? "" : " (not a champion)");
  if (c.status == ChampionResult::Status::Diverged && !c.mismatches.empty()) {
    const Mismatch& m = c.mismatches.front();
    o << "  " << where(m) << ": logged " << m.logged << ", recomputed " << m.recomputed;
    o << "  (max error " << error_text(c.max_error) << "; "
      << plural(c.mismatch_count, "value differs", "values differ");
    if (c.poses_diverged > 0)
      o << ", " << c.poses_diverged << " of " << c.poses_compared << " poses from step " << c.first_divergent_step;
    o << ")";
  } else {
    o << "  spheres " << c.spheres << "  morphology " << (c.morphology_logged ? "same" : "not logged") << "  poses "
      << c.poses_compared;
    if (c.poses_expected > 0 && c.poses_expected != c.poses_logged)
      o << " (of " << c.poses_expected << " in its trajectory)";
    if (c.poses_logged == 0 && c.recomputed_outcome > 0) o << " (none logged under this id)";
    if (c.same_genes_as >= 0)
      o << "  same genes as genome " << c.same_genes_as << " (gen " << c.same_genes_generation << ")";
    if (c.fitness_compared) o << "  fitness " << short_number(c.recomputed_fitness);
    if (c.max_error > 0) o << "  max error " << error_text(c.max_error);
  }
  for (const auto& p : c.problems) o << "  [" << p << "]";
  return o.str();
}

std::string format_text(const CheckReport& r) {
  std::ostringstream o;
  o << "robozoo-replay check " << r.log_path << ": " << r.events << " events";
  if (r.foreign_events) o << " (" << r.foreign_events << " of other channels ignored)";
  o << "\n";
  for (const auto& run : r.runs)
    o << "  run " << run.run_id << ": robozoo " << run.software_version << ", " << run.regime << ", seed " << run.seed
      << ", population " << run.population << ", " << run.generations << " generations\n";
  for (const auto& run : r.runs)
    if (r.forced && run.software_version != software_version())
      o << "  note: --force: run " << run.run_id << " (robozoo " << run.software_version << ") is checked with robozoo "
        << software_version() << "\n";
  if (!r.fatal.empty()) o << "UNUSABLE: " << r.fatal << "\n";
  const bool with_run = r.runs.size() > 1;
  for (const auto& c : r.champions) o << champion_line(c, with_run) << "\n";
  constexpr size_t kShown = 20;
  for (size_t i = 0; i < r.structure.size() && i < kShown; ++i) o << "DIVERGED " << describe(r.structure[i]) << "\n";
  if (r.structure.size() > kShown) o << "  ... and " << r.structure.size() - kShown << " more message differences\n";
  for (const auto& p : r.input_problems) {
    o << "input: ";
    if (p.eventnum >= 0) o << "event " << p.eventnum << " (" << p.channel << "): ";
    o << p.what << "\n";
  }
  int64_t poses = 0, morph = 0, fit = 0;
  for (const auto& c : r.champions) {
    poses += c.poses_compared;
    morph += c.morphology_logged;
    fit += c.fitness_compared;
  }
  o << "summary: " << plural(static_cast<int64_t>(r.champions.size()), "genome", "genomes")
    << " checked: " << r.count(ChampionResult::Status::Ok) << " ok, " << r.count(ChampionResult::Status::Diverged)
    << " diverged, " << r.count(ChampionResult::Status::Unusable) << " unusable; " << r.generations_proved
    << " generations' messages proved, "
    << plural(static_cast<int64_t>(r.structure.size()), "message differs", "messages differ") << "; " << morph
    << " morphologies, " << plural(poses, "pose", "poses") << " and " << fit << " fitnesses compared "
    << (r.tolerance > 0 ? "within a relative error of " + short_number(r.tolerance) : std::string("bit for bit"))
    << "; " << plural(static_cast<int64_t>(r.input_problems.size()), "input problem", "input problems");
  char secs[32];
  std::snprintf(secs, sizeof secs, "%.2f", r.seconds);
  o << "; " << secs << " s; exit " << r.exit_code() << "\n";
  return o.str();
}

nlohmann::json to_json(const CheckReport& r) {
  using nlohmann::json;
  json j;
  j["log"] = r.log_path;
  j["tolerance"] = r.tolerance;
  j["bit_for_bit"] = r.tolerance == 0.0;
  j["forced"] = r.forced;
  j["events"] = r.events;
  j["foreign_events"] = r.foreign_events;
  j["file_bytes"] = r.file_bytes;
  j["fatal"] = r.fatal.empty() ? json(nullptr) : json(r.fatal);
  j["runs"] = json::array();
  for (const auto& run : r.runs)
    j["runs"].push_back({{"run_id", run.run_id},
                         {"software_version", run.software_version},
                         {"seed", run.seed},
                         {"regime", run.regime},
                         {"population", run.population},
                         {"generations", run.generations}});
  j["champions"] = json::array();
  for (const auto& c : r.champions) {
    json m = json::array();
    for (const auto& x : c.mismatches)
      m.push_back({{"what", x.what},
                   {"step", x.step >= 0 ? json(x.step) : json(nullptr)},
                   {"element", x.element},
                   {"field", x.field},
                   {"logged", x.logged},
                   {"recomputed", x.recomputed},
                   {"error", error_json(x.error)}});
    j["champions"].push_back(
        {{"run_id", c.run_id},
         {"generation", c.generation},
         {"genome_id", c.genome_id},
         {"champion", c.champion},
         {"status", status_name(c.status)},
         {"problems", c.problems},
         {"spheres", c.spheres},
         {"same_genes_as", c.same_genes_as >= 0 ? json(c.same_genes_as) : json(nullptr)},
         {"morphology_logged", c.morphology_logged},
         {"morphology_same", c.morphology_ok},
         {"poses_logged", c.poses_logged},
         {"poses_expected", c.poses_expected},
         {"poses_compared", c.poses_compared},
         {"poses_diverged", c.poses_diverged},
         {"first_divergent_step", c.first_divergent_step >= 0 ? json(c.first_divergent_step) : json(nullptr)},
         {"fitness_compared", c.fitness_compared},
         {"logged_fitness", exact_text(c.logged_fitness)},
         {"recomputed_fitness", exact_text(c.recomputed_fitness)},
         {"logged_outcome", c.logged_outcome},
         {"recomputed_outcome", c.recomputed_outcome},
         {"values_compared", c.values_compared},
         {"mismatch_count", c.mismatch_count},
         {"max_error", error_json(c.max_error)},
         {"mismatches", m}});
  }
  j["generations_proved"] = r.generations_proved;
  j["structure"] = json::array();
  for (const auto& d : r.structure)
    j["structure"].push_back({{"eventnum", d.eventnum >= 0 ? json(d.eventnum) : json(nullptr)},
                              {"channel", d.channel},
                              {"run_id", d.run_id},
                              {"generation", d.generation},
                              {"field", d.field},
                              {"logged", d.logged},
                              {"expected", d.expected},
                              {"rule", d.rule}});
  j["input_problems"] = json::array();
  for (const auto& p : r.input_problems)
    j["input_problems"].push_back(
        {{"eventnum", p.eventnum >= 0 ? json(p.eventnum) : json(nullptr)}, {"channel", p.channel}, {"what", p.what}});
  j["summary"] = {{"genomes", r.champions.size()},
                  {"ok", r.count(ChampionResult::Status::Ok)},
                  {"diverged", r.count(ChampionResult::Status::Diverged)},
                  {"unusable", r.count(ChampionResult::Status::Unusable)},
                  {"message_differences", r.structure.size()},
                  {"input_problems", r.input_problems.size()},
                  {"seconds", r.seconds},
                  {"exit_code", r.exit_code()}};
  return j;
}

}  // namespace robozoo::replay
