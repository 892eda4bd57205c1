#pragma once
// Zoo sheets in the style of the paper's Figure 4: a grid of robots in their
// starting pose (leaves red, other spheres blue) on a lit ground, all seen from
// the same direction, each framed to fill its cell, with a caption under each.
#include <string>
#include <vector>

#include "render/gl/camera.hpp"
#include "render/gl/image.hpp"
#include "render/scene/robot_card.hpp"
#include "render/scene/stage.hpp"
#include "render/gl/text.hpp"

namespace robozoo::render {

struct ZooOptions {
  int cell_width = 360;     ///< width of each robot's picture (px)
  int cell_height = 270;    ///< height of each robot's picture (px)
  int columns = 0;          ///< robots per row; 0: about ceil(sqrt(2 n))
  int gap = 12;             ///< space around and between cells (px)
  int font_size = 15;       ///< caption size (px)
  int samples = 4;          ///< multisampling (samples per pixel)
  std::string title;        ///< line above the grid; empty: none
  bool same_scale = false;  ///< one camera distance for all (sizes comparable) instead of filling each cell
  /// With same_scale: a robot drawn at less than this fraction of the size that
  /// fills its cell also gets an inset in the cell's corner, framed to fill it
  /// and marked with its magnification (0: no insets).
  double inset_below = 0.35;
  bool grid = true;      ///< grid lines on the ground
  ViewAngles angles;     ///< the direction every robot is seen from
  double margin = 0.07;  ///< free fraction of a cell on each side
  std::string font_dir;  ///< DejaVu fonts; empty: the system's
};

/// Throws std::invalid_argument for sizes out of range.
void validate(const ZooOptions& o);

/// The camera that frames a robot's starting pose in a width x height cell.
Camera card_camera(const RobotCard& card, int width, int height, const ViewAngles& angles, double margin);

/// The 3D picture of one robot (no caption), drawn on `stage` at its size.
Image render_card(Stage& stage, const RobotCard& card, const Camera& camera, bool grid = true);

/// The whole sheet. Throws std::invalid_argument when `cards` is empty.
Image render_zoo(const std::vector<RobotCard>& cards, const ZooOptions& options);

/// One robot with its caption under it (live mode's latest.png).
Image render_card_with_caption(Stage& stage, Fonts& fonts, const RobotCard& card, const ZooOptions& options);

}  // namespace robozoo::render
