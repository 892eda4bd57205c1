#pragma once
// Innovation numbers and hidden-node ids, handed out within one generation so
// that the same structural mutation made by several genomes of one generation
// gets the same numbers (NEAT). Ordered maps only: nothing depends on hashing.
#include <cstdint>
#include <map>
#include <utility>

#include "evolve/cppn/activation.hpp"

namespace robozoo {

class InnovationTracker {
 public:
  InnovationTracker(int64_t next_innovation, int32_t next_node_id)
      : next_innovation_(next_innovation), next_node_id_(next_node_id) {}
  /// Innovation number for a new link from -> to (the same this generation for the same pair).
  int64_t link(int32_t from, int32_t to);
  /// Node id, the two link innovations and the node's activation for splitting
  /// the link with the given innovation. The first split of a link in a
  /// generation fixes the activation (`activation`); later identical splits in
  /// the same generation get the same node id, innovations and activation, so
  /// a node id means one node gene everywhere.
  struct Split {
    int32_t node;
    int64_t in_link;
    int64_t out_link;
    Activation activation;
  };
  /// `from`/`to` are the split link's endpoints: the new links from -> node and
  /// node -> to are also registered as link innovations of this generation.
  Split split(int64_t link_innovation, int32_t from, int32_t to, Activation activation = Activation::SignedSigmoid);
  /// HyperNEAT's split of from -> to: always a new node id, so the links from -> node and
  /// node -> to are new pairs of this generation and get new innovation numbers (link()).
  Split fresh_split(int32_t from, int32_t to, Activation activation);
  /// Forget this generation's mutations (numbers keep increasing).
  void new_generation();
  int64_t next_innovation() const { return next_innovation_; }
  int32_t next_node_id() const { return next_node_id_; }

 private:
  int64_t next_innovation_;
  int32_t next_node_id_;
  std::map<std::pair<int32_t, int32_t>, int64_t> links_;
  std::map<int64_t, Split> splits_;
};

}  // namespace robozoo
