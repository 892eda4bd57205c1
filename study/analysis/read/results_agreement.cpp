#include "study/analysis/read/results_agreement.hpp"

#include <algorithm>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "study/analysis/stats_job.hpp"

namespace robozoo {

using nlohmann::json;

namespace {

/// The same JSON text: bit-exact for doubles (nlohmann writes them round-trip,
/// -0 apart from 0), unlike json's operator==.
bool same(const json& a, const json& b) { return a.dump() == b.dump(); }

std::string differ(const std::string& where, const json& a, const json& b) {
  return where + ": " + a.dump() + " != " + b.dump();
}

/// The run object without the generations requested (there and in its configuration).
json run_identity(json run) {
  run.erase("generations");
  if (run.contains("config") && run["config"].is_object()) run["config"].erase("generations");
  return run;
}

std::string trial_name(const std::string& path) {
  std::string name = std::filesystem::path(path).filename().string();
  return name.substr(0, name.size() - std::string(kRunResultsExtension).size());
}

}  // namespace

std::optional<std::string> first_disagreement(const RunResults& ra, const RunResults& rb) {
  const json a = run_results_to_json(ra), b = run_results_to_json(rb);
  const json ia = run_identity(a.at("run")), ib = run_identity(b.at("run"));
  for (auto it = ia.begin(); it != ia.end(); ++it) {
    const json other = ib.contains(it.key()) ? ib.at(it.key()) : json(nullptr);
    if (it.key() == "config" && it->is_object() && other.is_object()) {
      // Name the first differing setting, not the whole configuration.
      const json flat_a = it->flatten(), flat_b = other.flatten();
      for (auto f = flat_a.begin(); f != flat_a.end(); ++f) {
        const json o = flat_b.contains(f.key()) ? flat_b.at(f.key()) : json(nullptr);
        if (!same(*f, o)) return differ("run.config" + f.key(), *f, o);
      }
      for (auto f = flat_b.begin(); f != flat_b.end(); ++f)
        if (!flat_a.contains(f.key())) return differ("run.config" + f.key(), json(nullptr), *f);
    } else if (!same(*it, other)) {
      return differ("run." + it.key(), *it, other);
    }
  }
  for (auto it = ib.begin(); it != ib.end(); ++it)
    if (!ia.contains(it.key())) return differ("run." + it.key(), json(nullptr), *it);

  const size_t n = std::min(ra.run.generations.size(), rb.run.generations.size());
  const json& ga = a.at("generations");
  const json& gb = b.at("generations");
  for (size_t g = 0; g < n; ++g)
    for (auto col = ga.begin(); col != ga.end(); ++col) {
      const json& x = col->at(g);
      const json& y = gb.at(col.key()).at(g);
      if (!same(x, y)) return differ("generation " + std::to_string(g) + ": " + col.key(), x, y);
    }

  // Champions of the common generations, in generation order.
  auto champions_before = [n](const json& champs) {
    std::vector<json> out;
    for (const auto& c : champs)
      if (c.at("generation").get<int64_t>() < static_cast<int64_t>(n)) out.push_back(c);
    return out;
  };
  const std::vector<json> ca = champions_before(a.at("champions")), cb = champions_before(b.at("champions"));
  for (size_t k = 0; k < std::max(ca.size(), cb.size()); ++k) {
    if (k >= ca.size() || k >= cb.size()) {
      const json& c = k < ca.size() ? ca[k] : cb[k];
      return "champions: generation " + c.at("generation").dump() + "'s champion is in " +
             (k < ca.size() ? "the first" : "the second") + " result only";
    }
    const std::string where = "champion of generation " + ca[k].at("generation").dump();
    for (auto f = ca[k].begin(); f != ca[k].end(); ++f) {
      const json o = cb[k].contains(f.key()) ? cb[k].at(f.key()) : json(nullptr);
      if (!same(*f, o)) return differ(where + ": " + f.key(), *f, o);
    }
  }

  // The best-of-run robot, when both won it within the common generations (a
  // longer run may have found a better one later).
  const json &ba = a.at("best"), &bb = b.at("best");
  if (!ba.is_null() && !bb.is_null() && ba.at("generation").get<int64_t>() < static_cast<int64_t>(n) &&
      bb.at("generation").get<int64_t>() < static_cast<int64_t>(n)) {
    for (auto f = ba.begin(); f != ba.end(); ++f) {
      const json o = bb.contains(f.key()) ? bb.at(f.key()) : json(nullptr);
      if (!same(*f, o)) return differ("best-of-run robot: " + f.key(), *f, o);
    }
  }
  return std::nullopt;
}

bool FolderAgreement::agree() const {
  if (trials.empty()) return false;
  return std::all_of(trials.begin(), trials.end(), [](const TrialAgreement& t) { return !t.difference; });
}

FolderAgreement compare_results_folders(const std::string& dir_a, const std::string& dir_b) {
  const std::vector<std::string> files_a = list_results(dir_a), files_b = list_results(dir_b);
  std::set<std::string> names_b;
  for (const auto& f : files_b) names_b.insert(trial_name(f));
  std::set<std::string> names_a;
  FolderAgreement out;
  for (const auto& fa : files_a) {
    const std::string name = trial_name(fa);
    names_a.insert(name);
    if (!names_b.count(name)) {
      out.only_a.push_back(name);
      continue;
    }
    const RunResults a = read_run_results(fa);
    const RunResults b = read_run_results((std::filesystem::path(dir_b) / (name + kRunResultsExtension)).string());
    TrialAgreement t;
    t.trial = name;
    t.generations_a = a.run.generations.size();
    t.generations_b = b.run.generations.size();
    t.difference = first_disagreement(a, b);
    out.trials.push_back(std::move(t));
  }
  for (const auto& fb : files_b)
    if (!names_a.count(trial_name(fb))) out.only_b.push_back(trial_name(fb));
  return out;
}

void print_agreement(const FolderAgreement& f, const std::string& dir_a, const std::string& dir_b, std::ostream& out) {
  size_t differing = 0;
  for (const auto& t : f.trials) {
    const size_t n = std::min(t.generations_a, t.generations_b);
    out << "  " << t.trial << ": generations 0-" << (n == 0 ? 0 : n - 1) << " (" << t.generations_a << " and "
        << t.generations_b << " held) ";
    if (t.difference) {
      ++differing;
      out << "DIFFER at " << *t.difference << "\n";
    } else {
      out << "agree\n";
    }
  }
  if (!f.only_a.empty()) out << "  only in " << dir_a << ": " << f.only_a.size() << " trials\n";
  if (!f.only_b.empty()) out << "  only in " << dir_b << ": " << f.only_b.size() << " trials\n";
  if (f.trials.empty())
    out << "no trial is in both " << dir_a << " and " << dir_b << ": nothing compared\n";
  else if (differing == 0)
    out << f.trials.size() << " trials in both folders agree over the generations both hold\n";
  else
    out << differing << " of " << f.trials.size() << " trials in both folders differ\n";
}

}  // namespace robozoo
