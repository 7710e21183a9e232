// A log-log chart of series of points, each point labelled: `billiard bench`'s speed against
// error, one series per method family, each point a tolerance.
#pragma once

#include <string>
#include <vector>

namespace billiard::plot {

struct ChartPoint {
  double x = 0.0, y = 0.0;  // > 0 (log axes); smaller values are drawn at the axes' floor
  std::string label;        // drawn beside the point
};

struct ChartSeries {
  std::string name;  // in the legend
  std::vector<ChartPoint> points;  // joined in this order
};

struct Chart {
  std::string title, x_label, y_label;
  double x_floor = 1e-3, y_floor = 1e-12;  // what a point below is drawn at
  std::vector<ChartSeries> series;
};

// Draws `chart` into `path` (.png or .svg), 1000 x 650 px; decades as grid lines. Throws
// std::invalid_argument for another extension, std::runtime_error when it cannot be written.
void DrawChart(const Chart& chart, const std::string& path);

}  // namespace billiard::plot
