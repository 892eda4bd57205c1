#include "render/scene/overlay.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace robozoo::render {

namespace {
const Rgb kPanel{18, 22, 30};
const Rgb kWhite{255, 255, 255};
const Rgb kSoft{210, 216, 226};
const Rgb kBar{240, 176, 32};

void disc(Image& img, int cx, int cy, double r, Rgb c) {
  for (int y = static_cast<int>(cy - r - 1); y <= cy + r + 1; ++y)
    for (int x = static_cast<int>(cx - r - 1); x <= cx + r + 1; ++x) {
      const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
      img.blend(x, y, c, std::clamp(r - d + 0.5, 0.0, 1.0));
    }
}
}  // namespace

void draw_overlay(Image& frame, Fonts& fonts, const OverlayText& t, int margin) {
  const int pad = std::max(6, fonts.regular.pixel_size() / 2);
  const int lh = fonts.regular.line_height();
  int w = fonts.bold.measure(t.title);
  for (const auto& l : t.lines) w = std::max(w, fonts.regular.measure(l));
  const int bar_h = t.progress >= 0 ? std::max(3, lh / 6) : 0;
  const int h = lh * static_cast<int>(1 + t.lines.size()) + (bar_h ? bar_h + pad / 2 : 0);
  frame.fill_rect(margin, margin, w + 2 * pad, h + 2 * pad, kPanel, 0.62);
  int baseline = margin + pad + fonts.regular.ascender();
  fonts.bold.draw(frame, margin + pad, baseline, t.title, kWhite);
  for (const auto& l : t.lines) {
    baseline += lh;
    fonts.regular.draw(frame, margin + pad, baseline, l, kSoft);
  }
  if (bar_h) {
    const int y = margin + pad + lh * static_cast<int>(1 + t.lines.size()) + pad / 2;
    frame.fill_rect(margin + pad, y, w, bar_h, kSoft, 0.25);
    const int filled = static_cast<int>(std::lround(std::clamp(t.progress, 0.0, 1.0) * w));
    frame.fill_rect(margin + pad, y, filled, bar_h, kBar, 0.95);
  }
}

void draw_legend(Image& frame, Font& font, Rgb leaf, Rgb inner, int margin) {
  const std::string a = "leaf sphere", b = "other sphere";
  const int r = std::max(4, font.pixel_size() / 3);
  const int gap = font.pixel_size() / 2;
  const int wa = font.measure(a), wb = font.measure(b);
  const int w = 2 * r + gap + wa + gap * 2 + 2 * r + gap + wb;
  const int pad = gap;
  const int h = font.line_height();
  const int x0 = frame.width() - margin - w - 2 * pad, y0 = frame.height() - margin - h - 2 * pad;
  frame.fill_rect(x0, y0, w + 2 * pad, h + 2 * pad, kPanel, 0.5);
  const int cy = y0 + pad + h / 2;
  const int baseline = y0 + pad + font.ascender();
  int x = x0 + pad;
  disc(frame, x + r, cy, r, leaf);
  x = font.draw(frame, x + 2 * r + gap, baseline, a, kSoft) + 2 * gap;
  disc(frame, x + r, cy, r, inner);
  font.draw(frame, x + 2 * r + gap, baseline, b, kSoft);
}

bool draw_target_pointer(Image& frame, Font& font, const Eigen::Vector3d& projected, const std::string& label,
                         Rgb color, int margin) {
  const double w = frame.width(), h = frame.height();
  const bool behind = projected.z() <= 0;
  if (!behind && projected.x() >= 0 && projected.x() < w && projected.y() >= 0 && projected.y() < h) return false;
  // Direction from the centre of the frame towards the target (flipped when
  // the point is behind the eye, where the projection mirrors it).
  Eigen::Vector2d d(projected.x() - w / 2, projected.y() - h / 2);
  if (behind) d = -d;
  if (d.norm() < 1e-9) d = Eigen::Vector2d(1, 0);
  d.normalize();
  // Where that ray leaves the frame, inset by the margin and the arrow's size.
  const double size = std::max(10.0, h / 28.0);
  const double inset = margin + size * 1.5;
  const double sx = d.x() != 0 ? (w / 2 - inset) / std::abs(d.x()) : 1e300;
  const double sy = d.y() != 0 ? (h / 2 - inset) / std::abs(d.y()) : 1e300;
  const Eigen::Vector2d tip = Eigen::Vector2d(w / 2, h / 2) + d * std::min(sx, sy);
  // A triangle pointing along d, anti-aliased by 4x4 supersampling.
  const Eigen::Vector2d n(-d.y(), d.x());
  const Eigen::Vector2d a = tip + d * size, b = tip - d * size * 0.6 + n * size * 0.8,
                        c = tip - d * size * 0.6 - n * size * 0.8;
  auto edge = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
  };
  const int x0 = static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))),
            x1 = static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()})));
  const int y0 = static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))),
            y1 = static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()})));
  const double sign = edge(a, b, c) > 0 ? 1.0 : -1.0;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      int inside = 0;
      for (int sy2 = 0; sy2 < 4; ++sy2)
        for (int sx2 = 0; sx2 < 4; ++sx2) {
          const Eigen::Vector2d p(x + (sx2 + 0.5) / 4, y + (sy2 + 0.5) / 4);
          inside += sign * edge(a, b, p) >= 0 && sign * edge(b, c, p) >= 0 && sign * edge(c, a, p) >= 0;
        }
      frame.blend(x, y, color, inside / 16.0 * 0.95);
    }
  // The label beside the arrow, towards the frame's inside.
  const int tw = font.measure(label);
  const Eigen::Vector2d at =
      tip - d * (size * 1.2 + 0.5 * tw * std::abs(d.x()) + 0.6 * font.line_height() * std::abs(d.y()));
  const int lx = static_cast<int>(std::lround(at.x() - tw / 2.0));
  const int ly = static_cast<int>(std::lround(at.y() + font.ascender() / 2.0));
  frame.fill_rect(lx - 4, ly - font.ascender() - 2, tw + 8, font.line_height() + 2, kPanel, 0.5);
  font.draw(frame, lx, ly, label, kWhite);
  return true;
}

}  // namespace robozoo::render
