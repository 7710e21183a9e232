#include "plot/reliability.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plot/canvas.h"

namespace billiard::plot {

void DrawReliability(const std::vector<ReliabilityBin>& bins, const std::string& title,
                     int min_count, const std::string& path) {
  constexpr int kSize = 700;
  constexpr double kMargin = 80, kSide = kSize - 2 * kMargin;
  Canvas canvas(path, kSize, kSize);
  cairo_t* cr = canvas.cr();
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  const auto px = [&](double p) { return kMargin + p * kSide; };
  const auto py = [&](double p) { return kSize - kMargin - p * kSide; };
  // Grid at every tenth, the axes' labels.
  cairo_set_line_width(cr, 0.5);
  for (int i = 0; i <= 10; ++i) {
    cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
    cairo_move_to(cr, px(i / 10.0), py(0));
    cairo_line_to(cr, px(i / 10.0), py(1));
    cairo_move_to(cr, px(0), py(i / 10.0));
    cairo_line_to(cr, px(1), py(i / 10.0));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    char label[8];
    std::snprintf(label, sizeof label, "%.1f", i / 10.0);
    Text(cr, px(i / 10.0), py(0) + 18, label, 11, 0.5);
    Text(cr, px(0) - 8, py(i / 10.0) + 4, label, 11, 1.0);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  Text(cr, kSize / 2.0, 35, title, 15, 0.5);
  Text(cr, kSize / 2.0, kSize - 30, "predicted probability of a legal pot", 13, 0.5);
  cairo_save(cr);
  cairo_translate(cr, 28, kSize / 2.0);
  cairo_rotate(cr, -M_PI / 2);
  Text(cr, 0, 0, "measured pot rate", 13, 0.5);
  cairo_restore(cr);
  // The diagonal, and the +-5 point band the acceptance allows.
  cairo_set_source_rgba(cr, 0.2, 0.6, 0.2, 0.15);
  cairo_move_to(cr, px(0), py(0.05));
  cairo_line_to(cr, px(0.95), py(1));
  cairo_line_to(cr, px(1), py(1));
  cairo_line_to(cr, px(1), py(0.95));
  cairo_line_to(cr, px(0.05), py(0));
  cairo_line_to(cr, px(0), py(0));
  cairo_close_path(cr);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0.2, 0.6, 0.2);
  cairo_set_line_width(cr, 1.0);
  cairo_move_to(cr, px(0), py(0));
  cairo_line_to(cr, px(1), py(1));
  cairo_stroke(cr);
  for (const ReliabilityBin& b : bins) {
    if (b.count == 0) continue;
    const double x = px(b.predicted), y = py(b.measured);
    const double sigma = std::sqrt(b.measured * (1 - b.measured) / b.count);
    cairo_set_source_rgb(cr, 0.1, 0.2, 0.7);
    cairo_set_line_width(cr, 1.2);
    cairo_move_to(cr, x, py(std::max(0.0, b.measured - 2 * sigma)));
    cairo_line_to(cr, x, py(std::min(1.0, b.measured + 2 * sigma)));
    cairo_stroke(cr);
    cairo_arc(cr, x, y, 5, 0, 2 * M_PI);
    if (b.count >= min_count) {
      cairo_fill(cr);
    } else {
      cairo_stroke(cr);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    Text(cr, x + 8, y - 6, "n=" + std::to_string(b.count), 10);
  }
  Text(cr, px(0) + 10, py(1) + 20, "bars: 2 binomial standard errors; hollow: fewer than " +
                                       std::to_string(min_count) + " shots; band: +-5 points",
       10);
  canvas.Finish();
}

}  // namespace billiard::plot
