// The straight stretches of the cloth's outline along a side (internal to the table finder,
// table_finder.h): at the search resolution, the outline points near a side of the quadrilateral the
// outline's hull reduces to, and the lines through them (RANSAC, Fischler and Bolles 1981, then
// least squares).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

namespace billiard::estimator {

// A line fitted to outline points: how far they are from it and how many there are.
struct Line {
  Eigen::Vector3d coefficients;  // a x + b y + c = 0, (a, b) unit
  double rms = 0;
  int points = 0;
};

// The outline points along the middle of the side from `a` to `b` (between 12 and 88 % of the way
// along it, away from the corner pockets; within 2 % of the hull's `perimeter` of it).
std::vector<cv::Point2d> SidePoints(const std::vector<cv::Point>& outline, const cv::Point2d& a,
                                    const cv::Point2d& b, double perimeter);

// The lines through the outline points near the side from `a` to `b`, best supported first: RANSAC
// (seeded, so that a frame always gives the same table) then least squares over its inliers, then
// again over the points left, while a line holds a tenth of the side's points (up to three lines;
// the first within 0.3 rad of the side's direction, the others within 0.15 rad; a turned line is
// the side only when no other is found). The cloth's outline along a side is a straight stretch
// where the cloth runs up to the cushion, and others where an arm or a cue hides it, where balls
// against a cushion seen from low cut it (their outlines in a row), or where the cushion's top, of
// the cloth's colour, joins the bed for a while: the best supported line may bridge two of them,
// and one of the others be the side.
std::vector<Line> FitSides(const std::vector<cv::Point>& outline, const cv::Point2d& a,
                           const cv::Point2d& b, double perimeter);

}  // namespace billiard::estimator
