#include "render/overlay.hpp"

#include <algorithm>
#include <cmath>

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
  const int w = 2 * r + gap / 2 + wa + gap * 2 + 2 * r + gap / 2 + wb;
  const int pad = gap;
  const int h = font.line_height();
  const int x0 = frame.width() - margin - w - 2 * pad, y0 = frame.height() - margin - h - 2 * pad;
  frame.fill_rect(x0, y0, w + 2 * pad, h + 2 * pad, kPanel, 0.5);
  const int cy = y0 + pad + h / 2;
  const int baseline = y0 + pad + font.ascender();
  int x = x0 + pad;
  disc(frame, x + r, cy, r, leaf);
  x = font.draw(frame, x + 2 * r + gap / 2, baseline, a, kSoft) + 2 * gap;
  disc(frame, x + r, cy, r, inner);
  font.draw(frame, x + 2 * r + gap / 2, baseline, b, kSoft);
}

}  // namespace robozoo::render
