#include "render/zoo/zoo_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace robozoo::render {

namespace {

const Rgb kPaper{255, 255, 255};
const Rgb kBorder{205, 208, 214};
const Rgb kInk{30, 32, 38};
const Rgb kMuted{88, 92, 102};

int caption_height(const Fonts& f) { return 2 * f.regular.line_height() + 10; }

/// `text` shortened with an ellipsis until it fits `width` pixels.
std::string fit(Font& font, std::string text, int width) {
  if (font.measure(text) <= width) return text;
  const std::string dots = "\u2026";
  while (!text.empty()) {
    // Drop one UTF-8 character from the end.
    size_t cut = text.size() - 1;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xc0) == 0x80) --cut;
    text.erase(cut);
    while (!text.empty() && text.back() == ' ') text.pop_back();
    if (font.measure(text + dots) <= width) return text + dots;
  }
  return "";
}

/// Draws a caption centred under a cell whose left edge is x, top y, width w;
/// lines too long for the cell are shortened.
void draw_caption(Image& sheet, Fonts& fonts, const RobotCard& card, int x, int y, int w) {
  const std::vector<std::string> lines = card_caption(card);
  Font* faces[2] = {&fonts.bold, &fonts.regular};
  const Rgb colors[2] = {kInk, kMuted};
  int baseline = y + 4 + fonts.regular.ascender();
  for (size_t i = 0; i < lines.size() && i < 2; ++i) {
    const std::string line = fit(*faces[i], lines[i], w - 4);
    const int tw = faces[i]->measure(line);
    faces[i]->draw(sheet, x + std::max(0, (w - tw) / 2), baseline, line, colors[i]);
    baseline += fonts.regular.line_height();
  }
}

void frame(Image& sheet, int x, int y, int w, int h) {
  sheet.fill_rect(x - 1, y - 1, w + 2, 1, kBorder);
  sheet.fill_rect(x - 1, y + h, w + 2, 1, kBorder);
  sheet.fill_rect(x - 1, y, 1, h, kBorder);
  sheet.fill_rect(x + w, y, 1, h, kBorder);
}

/// `image` shrunk by an integer factor (the mean of each factor x factor block).
Image shrink(const Image& image, int factor) {
  const int w = image.width() / factor, h = image.height() / factor;
  Image out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int sum[3] = {0, 0, 0};
      for (int dy = 0; dy < factor; ++dy) {
        const uint8_t* p = image.row(y * factor + dy) + 3 * x * factor;
        for (int dx = 0; dx < factor; ++dx)
          for (int c = 0; c < 3; ++c) sum[c] += p[3 * dx + c];
      }
      uint8_t* q = out.row(y) + 3 * x;
      for (int c = 0; c < 3; ++c) q[c] = static_cast<uint8_t>(sum[c] / (factor * factor));
    }
  return out;
}

/// The robot framed to fill a third of the cell, in the cell's top-right
/// corner, with its magnification over the common scale written under it.
void draw_inset(Image& sheet, Fonts& fonts, Stage& stage, const RobotCard& card, const Camera& own, double magnify,
                int x, int y, int w, bool grid) {
  const Image small = shrink(render_card(stage, card, own, grid), 3);
  const int ix = x + w - small.width() - 4, iy = y + 4;
  sheet.paste(small, ix, iy);
  frame(sheet, ix, iy, small.width(), small.height());
  char label[32];
  std::snprintf(label, sizeof label, "\u00d7%.0f", magnify);
  const int tw = fonts.regular.measure(label);
  const int lh = fonts.regular.line_height();
  sheet.fill_rect(ix + small.width() - tw - 6, iy + small.height() - lh - 2, tw + 6, lh + 2, kPaper, 0.8);
  fonts.regular.draw(sheet, ix + small.width() - tw - 3, iy + small.height() - lh - 2 + fonts.regular.ascender(), label,
                     kInk);
}

}  // namespace

void validate(const ZooOptions& o) {
  if (o.cell_width < 16 || o.cell_height < 16 || o.cell_width > 4096 || o.cell_height > 4096)
    throw std::invalid_argument("cell size must be between 16 and 4096 pixels, got " + std::to_string(o.cell_width) +
                                "x" + std::to_string(o.cell_height));
  if (o.columns < 0 || o.columns > 256) throw std::invalid_argument("columns must be in [0, 256]");
  if (o.gap < 0 || o.gap > 512) throw std::invalid_argument("gap must be in [0, 512] pixels");
  if (o.font_size < 6 || o.font_size > 128) throw std::invalid_argument("font size must be in [6, 128] pixels");
  if (!(o.margin >= 0 && o.margin < 0.45)) throw std::invalid_argument("margin must be in [0, 0.45)");
  if (!(o.inset_below >= 0 && o.inset_below <= 1)) throw std::invalid_argument("inset threshold must be in [0, 1]");
}

Camera card_camera(const RobotCard& card, int width, int height, const ViewAngles& angles, double margin) {
  return frame_spheres(card.shape.start, card.shape.radius, static_cast<double>(width) / height, angles, margin);
}

Image render_card(Stage& stage, const RobotCard& card, const Camera& camera, bool grid) {
  SceneView view;
  view.spheres = card.shape.at_start();
  view.grid = grid;
  return stage.render(view, camera);
}

Image render_zoo(const std::vector<RobotCard>& cards, const ZooOptions& o) {
  validate(o);
  if (cards.empty()) throw std::invalid_argument("no robots to draw");
  const int n = static_cast<int>(cards.size());
  const int columns =
      o.columns > 0 ? std::min(o.columns, n) : std::min(n, static_cast<int>(std::ceil(std::sqrt(2.0 * n))));
  const int rows = (n + columns - 1) / columns;
  Fonts fonts = Fonts::load(o.font_size, o.font_dir);
  Fonts title_fonts = Fonts::load(o.font_size * 3 / 2, o.font_dir);
  const int cap = caption_height(fonts);
  const int title_h = o.title.empty() ? 0 : title_fonts.bold.line_height() + o.gap;
  const int width = o.gap + columns * (o.cell_width + o.gap);
  const int height = o.gap + title_h + rows * (o.cell_height + cap + o.gap);
  Image sheet(width, height, kPaper);
  if (!o.title.empty()) {
    const std::string title = fit(title_fonts.bold, o.title, width - 2 * o.gap);
    const int tw = title_fonts.bold.measure(title);
    title_fonts.bold.draw(sheet, std::max(o.gap, (width - tw) / 2), o.gap + title_fonts.bold.ascender(), title, kInk);
  }

  std::vector<Camera> cameras;
  for (const RobotCard& c : cards) cameras.push_back(card_camera(c, o.cell_width, o.cell_height, o.angles, o.margin));
  const std::vector<Camera> own = cameras;
  if (o.same_scale) {
    double d = 0;
    for (const Camera& c : cameras) d = std::max(d, (c.eye - c.target).norm());
    for (Camera& c : cameras) {
      c.eye = c.target + (c.eye - c.target).normalized() * d;
      c.near_m = std::max(1e-3, 0.05 * d);
      c.far_m = 40.0 * d + 10.0;
    }
  }
  Stage stage(o.cell_width, o.cell_height, o.samples);
  for (int i = 0; i < n; ++i) {
    const int x = o.gap + (i % columns) * (o.cell_width + o.gap);
    const int y = o.gap + title_h + (i / columns) * (o.cell_height + cap + o.gap);
    const size_t k = static_cast<size_t>(i);
    sheet.paste(render_card(stage, cards[k], cameras[k], o.grid), x, y);
    // Drawn smaller than inset_below of the size that would fill the cell: an inset that it fills.
    const double fill = (own[k].eye - own[k].target).norm() / (cameras[k].eye - cameras[k].target).norm();
    if (o.same_scale && o.inset_below > 0 && fill < o.inset_below)
      draw_inset(sheet, fonts, stage, cards[k], own[k], 1.0 / fill, x, y, o.cell_width, o.grid);
    frame(sheet, x, y, o.cell_width, o.cell_height);
    draw_caption(sheet, fonts, cards[k], x, y + o.cell_height, o.cell_width);
  }
  return sheet;
}

Image render_card_with_caption(Stage& stage, Fonts& fonts, const RobotCard& card, const ZooOptions& o) {
  validate(o);
  stage.resize(o.cell_width, o.cell_height);
  const int cap = caption_height(fonts);
  Image out(o.cell_width + 2 * o.gap, o.cell_height + cap + 2 * o.gap, kPaper);
  const Camera cam = card_camera(card, o.cell_width, o.cell_height, o.angles, o.margin);
  out.paste(render_card(stage, card, cam, o.grid), o.gap, o.gap);
  frame(out, o.gap, o.gap, o.cell_width, o.cell_height);
  draw_caption(out, fonts, card, o.gap, o.gap + o.cell_height, o.cell_width);
  return out;
}

}  // namespace robozoo::render
