#include "replay/check/recompute_cache.hpp"

namespace robozoo::replay {

namespace {
uint64_t genes_hash(const Genome& g) {
  Genome anonymous = g;
  anonymous.id = 0;
  return genome_hash(anonymous);
}
}  // namespace

const RecomputeCache::Entry* RecomputeCache::find(const Genome& genome, const std::string& config) const {
  const auto it = entries_.find(genes_hash(genome));
  if (it == entries_.end()) return nullptr;
  for (const auto& e : it->second) {
    if (e->config == config && e->genes.nodes == genome.nodes && e->genes.links == genome.links) {
      ++hits_;
      return e.get();
    }
  }
  return nullptr;
}

const RecomputeCache::Entry& RecomputeCache::add(Entry e) {
  e.genes.id = 0;
  auto& bucket = entries_[genes_hash(e.genes)];
  bucket.push_back(std::make_unique<Entry>(std::move(e)));
  ++size_;
  return *bucket.back();
}

}  // namespace robozoo::replay
