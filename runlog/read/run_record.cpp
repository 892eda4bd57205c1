#include "runlog/read/run_record.hpp"

namespace robozoo {

const generation_t* RunRecord::generation(int32_t g) const {
  for (auto it = generations.rbegin(); it != generations.rend(); ++it)
    if (it->generation == g) return &*it;
  return nullptr;
}

GenomeRecord* RunRecord::find(int64_t genome_id) const {
  auto it = by_id.find(genome_id);
  return it == by_id.end() ? nullptr : it->second;
}

}  // namespace robozoo
