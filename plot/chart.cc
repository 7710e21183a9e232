#include "plot/chart.h"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "plot/canvas.h"

namespace billiard::plot {

namespace {

constexpr double kLabelSize = 10.0;  // [px]

// A label's box on the picture.
struct Box {
  double x0, y0, x1, y1;
  bool Overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// Draws `label` beside the point (x, y) where it overlaps no label placed before: right of the
// point above it, below it, then ever farther above and below with a thin line back to the
// point (neighbouring tolerances of one method often sit a few pixels apart).
void PlaceLabel(cairo_t* cr, double x, double y, const std::string& label,
                std::vector<Box>* placed) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, kLabelSize);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, label.c_str(), &extents);
  const double line = kLabelSize + 3.0;
  Box box{};
  double baseline = y - 7.0;
  for (int k = 0; k < 40; ++k) {
    // Offsets in turn: -7 (above), +15 (below), then a line farther each way.
    const double offset = k % 2 == 0 ? -7.0 - line * (k / 2) : 15.0 + line * (k / 2);
    baseline = y + offset;
    box = {x + 6.0, baseline - kLabelSize, x + 6.0 + extents.x_advance, baseline + 2.0};
    if (std::none_of(placed->begin(), placed->end(), [&](const Box& b) { return b.Overlaps(box); })) {
      break;
    }
  }
  placed->push_back(box);
  if (std::abs(baseline - y) > 16.0) {  // moved away: a leader line to its point
    cairo_set_line_width(cr, 0.6);
    cairo_move_to(cr, x + 3.0, y);
    cairo_line_to(cr, x + 6.0, baseline - 0.3 * kLabelSize);
    cairo_stroke(cr);
  }
  Text(cr, x + 6.0, baseline, label, kLabelSize);
}

}  // namespace

void DrawChart(const Chart& chart, const std::string& path) {
  constexpr int kWidth = 1000, kHeight = 650;
  constexpr double kLeft = 80, kRight = 230, kTop = 50, kBottom = 70;
  double x_min = 1e300, x_max = -1e300, y_min = 1e300, y_max = -1e300;
  const auto lx = [&](double x) { return std::log10(std::max(x, chart.x_floor)); };
  const auto ly = [&](double y) { return std::log10(std::max(y, chart.y_floor)); };
  for (const ChartSeries& s : chart.series) {
    for (const ChartPoint& p : s.points) {
      x_min = std::min(x_min, lx(p.x)), x_max = std::max(x_max, lx(p.x));
      y_min = std::min(y_min, ly(p.y)), y_max = std::max(y_max, ly(p.y));
    }
  }
  if (x_min > x_max) x_min = x_max = y_min = y_max = 0.0;  // nothing to draw: one decade
  x_min = std::floor(x_min), x_max = std::max(std::ceil(x_max + 1e-9), x_min + 1);
  y_min = std::floor(y_min), y_max = std::max(std::ceil(y_max + 1e-9), y_min + 1);
  const auto px = [&](double x) {
    return kLeft + (lx(x) - x_min) / (x_max - x_min) * (kWidth - kLeft - kRight);
  };
  const auto py = [&](double y) {
    return kHeight - kBottom - (ly(y) - y_min) / (y_max - y_min) * (kHeight - kTop - kBottom);
  };

  Canvas canvas(path, kWidth, kHeight);
  cairo_t* cr = canvas.cr();
  cairo_set_line_width(cr, 1.0);
  for (double d = x_min; d <= x_max; ++d) {
    const double x = px(std::pow(10.0, d));
    cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
    cairo_move_to(cr, x, kTop);
    cairo_line_to(cr, x, kHeight - kBottom);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    Text(cr, x, kHeight - kBottom + 18, "1e" + std::to_string(static_cast<int>(d)), 12, 0.5);
  }
  for (double d = y_min; d <= y_max; ++d) {
    const double y = py(std::pow(10.0, d));
    cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
    cairo_move_to(cr, kLeft, y);
    cairo_line_to(cr, kWidth - kRight, y);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    Text(cr, kLeft - 6, y + 4, "1e" + std::to_string(static_cast<int>(d)), 12, 1.0);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_rectangle(cr, kLeft, kTop, kWidth - kLeft - kRight, kHeight - kTop - kBottom);
  cairo_stroke(cr);
  Text(cr, kLeft, 28, chart.title, 15);
  Text(cr, 0.5 * (kLeft + kWidth - kRight), kHeight - 25, chart.x_label, 13, 0.5);
  cairo_save(cr);
  cairo_translate(cr, 22, 0.5 * (kTop + kHeight - kBottom));
  cairo_rotate(cr, -0.5 * M_PI);
  Text(cr, 0, 0, chart.y_label, 13, 0.5);
  cairo_restore(cr);

  static const std::array<std::array<double, 3>, 6> kColours = {{{0.80, 0.25, 0.10},
                                                                 {0.10, 0.55, 0.15},
                                                                 {0.10, 0.20, 0.80},
                                                                 {0.60, 0.15, 0.65},
                                                                 {0.00, 0.55, 0.75},
                                                                 {0.45, 0.45, 0.45}}};
  std::vector<Box> placed;
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const ChartSeries& s = chart.series[k];
    const auto& c = kColours[k % kColours.size()];
    cairo_set_source_rgb(cr, c[0], c[1], c[2]);
    cairo_set_line_width(cr, 2.0);
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const double x = px(s.points[i].x), y = py(s.points[i].y);
      i == 0 ? cairo_move_to(cr, x, y) : cairo_line_to(cr, x, y);
    }
    cairo_stroke(cr);
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const ChartPoint& p = s.points[i];
      cairo_set_source_rgb(cr, c[0], c[1], c[2]);
      cairo_arc(cr, px(p.x), py(p.y), 4.5, 0, 2 * M_PI);
      cairo_fill(cr);
      cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
      PlaceLabel(cr, px(p.x), py(p.y), p.label, &placed);
    }
    const double legend_y = kTop + 15 + 24.0 * k;
    cairo_set_source_rgb(cr, c[0], c[1], c[2]);
    cairo_arc(cr, kWidth - kRight + 22, legend_y - 4, 5, 0, 2 * M_PI);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    Text(cr, kWidth - kRight + 34, legend_y, s.name, 12);
  }
  canvas.Finish();
}

}  // namespace billiard::plot
