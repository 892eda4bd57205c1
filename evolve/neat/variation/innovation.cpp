#include "evolve/neat/variation/innovation.hpp"

namespace robozoo {

int64_t InnovationTracker::link(int32_t from, int32_t to) {
  const auto key = std::make_pair(from, to);
  const auto it = links_.find(key);
  if (it != links_.end()) return it->second;
  const int64_t innovation = next_innovation_++;
  links_.emplace(key, innovation);
  return innovation;
}

InnovationTracker::Split InnovationTracker::split(int64_t link_innovation, int32_t from, int32_t to,
                                                  Activation activation) {
  const auto it = splits_.find(link_innovation);
  if (it != splits_.end()) return it->second;
  Split s;
  s.node = next_node_id_++;
  s.in_link = next_innovation_++;
  s.out_link = next_innovation_++;
  s.activation = activation;
  splits_.emplace(link_innovation, s);
  links_.emplace(std::make_pair(from, s.node), s.in_link);
  links_.emplace(std::make_pair(s.node, to), s.out_link);
  return s;
}

InnovationTracker::Split InnovationTracker::fresh_split(int32_t from, int32_t to, Activation activation) {
  Split s;
  s.node = next_node_id_++;
  s.in_link = link(from, s.node);
  s.out_link = link(s.node, to);
  s.activation = activation;
  return s;
}

void InnovationTracker::new_generation() {
  links_.clear();
  splits_.clear();
}

}  // namespace robozoo
