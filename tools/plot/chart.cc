#include "tools/plot/chart.h"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "tools/plot/canvas.h"

namespace billiard::plot {

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
      // Above and below in turn: neighbouring tolerances often sit a few pixels apart.
      cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
      Text(cr, px(p.x) + 6, py(p.y) + (i % 2 == 0 ? -7 : 15), p.label, 10);
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
