// The straight stretches of a cloth's outline along a side (outline_stretches.h), on outlines drawn
// with their truth: a side the cloth runs up to, and a row of balls against a foreshortened short
// side, whose outlines line up on a line turned from the side and hold more of its points.
#include "estimator/outline_stretches.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace billiard::estimator {
namespace {

// The direction of a line a x + b y + c = 0 [rad], modulo pi.
double Direction(const Line& line) {
  return std::atan2(line.coefficients.x(), -line.coefficients.y());
}

// The turn between two directions modulo pi [rad].
double Turn(double a, double b) {
  const double d = std::fmod(std::abs(a - b), M_PI);
  return std::min(d, M_PI - d);
}

// Outline points every pixel from `from` to `to` (rounded, as a contour's are).
void AddSegment(const cv::Point2d& from, const cv::Point2d& to, std::vector<cv::Point>* outline) {
  const int steps = static_cast<int>(std::ceil(cv::norm(to - from)));
  for (int i = 0; i <= steps; ++i) {
    const cv::Point2d p = from + (to - from) * (static_cast<double>(i) / steps);
    outline->emplace_back(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y)));
  }
}

TEST(FitSides, AStraightSideIsItsOwnLine) {
  const cv::Point2d a(0, 0), b(200, 0);
  std::vector<cv::Point> outline;
  AddSegment(a, b, &outline);
  const std::vector<Line> lines = FitSides(outline, a, b, 600);
  ASSERT_FALSE(lines.empty());
  EXPECT_NEAR(Turn(Direction(lines.front()), 0.0), 0.0, 1e-6);
  EXPECT_NEAR(lines.front().coefficients.z(), 0.0, 1e-6);
  EXPECT_LT(lines.front().rms, 1e-6);
}

// A short side from (0, 0) to (40, 30) (seen from low, as in the hard suite's 15-degree frames):
// the cloth reaches it only near its ends, and between them its outline runs along a line turned
// 0.38 rad from it, through more points (the inner edges of balls against the cushion, in a row).
// That line is not the side: the side's own stretch comes first.
TEST(FitSides, ARowOfBallsTurnedFromTheSideIsNotIt) {
  const cv::Point2d a(0, 0), b(40, 30);
  const double side = std::atan2(b.y - a.y, b.x - a.x);
  const double turned = side + 0.38;
  const cv::Point2d along_turned(std::cos(turned), std::sin(turned));
  std::vector<cv::Point> outline;
  AddSegment(a, a + 0.35 * (b - a), &outline);  // the cloth up to the side
  AddSegment(a + 0.85 * (b - a), b, &outline);  // and again near its far end
  AddSegment(a + 6.0 * along_turned, a + 42.0 * along_turned, &outline);  // the balls' row
  const double perimeter = 2 * (200 + cv::norm(b - a));
  const std::vector<Line> lines = FitSides(outline, a, b, perimeter);
  ASSERT_FALSE(lines.empty());
  EXPECT_LT(Turn(Direction(lines.front()), side), 0.05);
  // Without the side's stretches, the turned line is all there is, and it is given.
  std::vector<cv::Point> row;
  AddSegment(a + 6.0 * along_turned, a + 42.0 * along_turned, &row);
  const std::vector<Line> only = FitSides(row, a, b, perimeter);
  ASSERT_EQ(only.size(), 1u);
  EXPECT_NEAR(Turn(Direction(only.front()), turned), 0.0, 0.05);
}

}  // namespace
}  // namespace billiard::estimator
