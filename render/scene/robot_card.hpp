#pragma once
// One robot to draw with its caption: who it is (run, regime, generation,
// fitness) and its shape.
#include <cstdint>
#include <string>
#include <vector>

#include "render/scene/robot_shape.hpp"
#include "runlog/read/run_record.hpp"

namespace robozoo::render {

struct RobotCard {
  std::string run_id;
  int regime = 0;  ///< run_t.regime: 0 feed-forward, 1 recurrent
  int32_t generation = 0;
  int64_t genome_id = 0;
  double fitness = 0.0;  ///< f = r + d
  double r_term = 0.0;   ///< (points)
  double d_term = 0.0;   ///< (m)
  RobotShape shape;
  std::vector<std::string> caption;  ///< replaces the default caption lines when not empty
};

/// Throws std::invalid_argument when the genome has no (consistent) morphology.
RobotCard make_card(const RunRecord& run, const GenomeRecord& genome);

/// "feed-forward" or "recurrent".
std::string regime_label(int regime);
/// The two caption lines: card.caption when it has any, else the run id, then
/// "regime · generation G · fitness F".
std::vector<std::string> card_caption(const RobotCard& card);

}  // namespace robozoo::render
