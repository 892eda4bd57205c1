#pragma once
// The information drawn over a video frame: who the robot is and the
// simulated time, on a translucent panel in the top-left corner.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "render/gl/image.hpp"
#include "render/gl/text.hpp"

namespace robozoo::render {

struct OverlayText {
  std::string title;               ///< first line, bold
  std::vector<std::string> lines;  ///< further lines, regular
  double progress = -1.0;          ///< 0-1: a thin bar under the text; < 0: none
};

/// Draws the panel; its size follows the text. `margin` is the distance from
/// the image's corner (px).
void draw_overlay(Image& frame, Fonts& fonts, const OverlayText& text, int margin);

/// A small colour key in the bottom-right corner: red = leaf, blue = other.
void draw_legend(Image& frame, Font& font, Rgb leaf, Rgb inner, int margin);

/// When the target is off screen: an arrow on the frame's edge pointing at it,
/// labelled. `projected` is project_to_pixel's result (z < 0: behind the eye).
/// Returns false (draws nothing) when the target is in view.
bool draw_target_pointer(Image& frame, Font& font, const Eigen::Vector3d& projected, const std::string& label,
                         Rgb color, int margin);

}  // namespace robozoo::render
