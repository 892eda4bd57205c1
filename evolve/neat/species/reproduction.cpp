#include "evolve/neat/species/reproduction.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace robozoo {

bool is_stagnant(const Species& s, int32_t generation, const NeatParams& p) {
  return generation - s.last_improvement >= p.dropoff_age;
}

double species_adjusted_fitness(const Species& s, const std::vector<double>& fitness, int32_t generation,
                                const NeatParams& p) {
  if (s.members.empty()) return 0.0;
  const double size = static_cast<double>(s.members.size());
  double shared = 0.0;
  for (int m : s.members) shared += fitness.at(static_cast<size_t>(m)) / size;
  return is_stagnant(s, generation, p) ? shared * p.dropoff_factor : shared;
}

std::vector<int> allocate_offspring(const std::vector<double>& shares, int total, const std::vector<double>& fallback) {
  if (total < 0) throw std::invalid_argument("allocate_offspring: negative total " + std::to_string(total));
  if (shares.size() != fallback.size())
    throw std::invalid_argument("allocate_offspring: " + std::to_string(shares.size()) + " shares but " +
                                std::to_string(fallback.size()) + " fallback weights");
  auto sum_of = [](const std::vector<double>& v, const char* what) {
    double s = 0.0;
    for (double x : v) {
      if (!std::isfinite(x) || x < 0.0)
        throw std::invalid_argument(std::string("allocate_offspring: ") + what + " must be finite and >= 0, got " +
                                    std::to_string(x));
      s += x;
    }
    return s;
  };
  const double sum_shares = sum_of(shares, "shares");
  const double sum_fallback = sum_of(fallback, "fallback weights");
  std::vector<int> counts(shares.size(), 0);
  if (total == 0) return counts;
  const std::vector<double>& w = sum_shares > 0.0 ? shares : fallback;
  const double sum = sum_shares > 0.0 ? sum_shares : sum_fallback;
  if (!(sum > 0.0)) throw std::invalid_argument("allocate_offspring: no species has a positive weight");

  std::vector<double> frac(w.size());
  int given = 0;
  for (size_t i = 0; i < w.size(); ++i) {
    const double quota = w[i] / sum * total;
    const double fl = std::min(std::floor(quota), static_cast<double>(total));
    counts[i] = static_cast<int>(fl);
    frac[i] = quota - fl;
    given += counts[i];
  }
  // Rounding can only leave offspring over, never take more than total; guard anyway.
  while (given > total) {
    const size_t i = static_cast<size_t>(std::max_element(counts.begin(), counts.end()) - counts.begin());
    --counts[i];
    --given;
  }
  std::vector<size_t> order(w.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return frac[a] > frac[b]; });
  // Species with no weight at all get nothing from the remainder.
  size_t k = 0;
  while (given < total) {
    const size_t i = order[k % order.size()];
    if (w[i] > 0.0) {
      ++counts[i];
      ++given;
    }
    ++k;
  }
  return counts;
}

std::vector<int> allocate_offspring_skim(const std::vector<std::vector<double>>& member_values, int total) {
  if (total < 0) throw std::invalid_argument("allocate_offspring_skim: negative total " + std::to_string(total));
  double sum = 0.0;
  size_t members = 0;
  for (const auto& species : member_values)
    for (double v : species) {
      if (!std::isfinite(v) || v < 0.0)
        throw std::invalid_argument("allocate_offspring_skim: values must be finite and >= 0, got " +
                                    std::to_string(v));
      sum += v;
      ++members;
    }
  if (!(sum > 0.0)) throw std::invalid_argument("allocate_offspring_skim: no member has a positive value");
  const double mean = sum / static_cast<double>(members);
  std::vector<int> counts(member_values.size(), 0);
  double skim = 0.0;
  int given = 0;
  for (size_t s = 0; s < member_values.size(); ++s) {
    for (double v : member_values[s]) {
      const double expected = v / mean;
      const double whole = std::floor(expected);
      counts[s] += static_cast<int>(whole);
      skim += std::fmod(expected, 1.0);
      if (skim > 1.0) {
        const double carried = std::floor(skim);
        counts[s] += static_cast<int>(carried);
        skim -= carried;
      }
    }
    given += counts[s];
  }
  if (given < total && !counts.empty()) {
    size_t best = 0;
    int most = 0;
    for (size_t s = 0; s < counts.size(); ++s)
      if (counts[s] >= most) {
        most = counts[s];
        best = s;
      }
    ++counts[best];
    if (++given < total) {
      std::fill(counts.begin(), counts.end(), 0);
      counts[best] = total;
      given = total;
    }
  }
  while (given > total) {
    --counts[static_cast<size_t>(std::max_element(counts.begin(), counts.end()) - counts.begin())];
    --given;
  }
  return counts;
}

std::vector<int> allocate_offspring_best_first(const std::vector<double>& shares, int total,
                                               const std::vector<size_t>& species_by_rank) {
  if (total < 0) throw std::invalid_argument("allocate_offspring_best_first: negative total " + std::to_string(total));
  double sum = 0.0;
  for (double x : shares) {
    if (!std::isfinite(x) || x < 0.0)
      throw std::invalid_argument("allocate_offspring_best_first: shares must be finite and >= 0, got " +
                                  std::to_string(x));
    sum += x;
  }
  std::vector<int> counts(shares.size(), 0);
  int given = 0;
  if (sum > 0.0)
    for (size_t i = 0; i < shares.size(); ++i) {
      counts[i] = std::min(static_cast<int>(shares[i] / sum * total), total - given);
      given += counts[i];
    }
  if (given < total && species_by_rank.empty())
    throw std::invalid_argument("allocate_offspring_best_first: offspring left over but no genome ranked");
  for (size_t k = 0; given < total; k = (k + 1) % species_by_rank.size()) {
    const size_t s = species_by_rank[k];
    if (s >= counts.size())
      throw std::invalid_argument("allocate_offspring_best_first: rank " + std::to_string(k) + " names species " +
                                  std::to_string(s) + " of " + std::to_string(counts.size()));
    ++counts[s];
    ++given;
  }
  return counts;
}

int num_parents(int species_size, const NeatParams& p) {
  if (species_size <= 0) return 0;
  const int n = static_cast<int>(std::floor(p.survival_threshold * species_size)) + 1;
  return std::clamp(n, 1, species_size);
}

}  // namespace robozoo
