#include "plot/labels.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace billiard::plot {

namespace {

using Eigen::Vector2d;

constexpr double kGapPx = 2.0;   // between a ball and its label
constexpr int kDirections = 8;   // places round a ball on one ring
constexpr int kRings = 4;        // rings, each kRingStepPx further out
constexpr double kRingStepPx = 8.0;
constexpr double kPi = 3.14159265358979323846;

double OverlapArea(const LabelBox& a, const LabelBox& b) {
  const double w = std::min(a.max.x(), b.max.x()) - std::max(a.min.x(), b.min.x());
  const double h = std::min(a.max.y(), b.max.y()) - std::max(a.min.y(), b.min.y());
  return w > 0.0 && h > 0.0 ? w * h : 0.0;
}

// The box of a label of `size` whose nearest corner or edge sits `distance` from `centre` in
// direction `angle` (picture y down; angle 0 right, pi/4 upper right).
LabelBox BoxAt(const Vector2d& centre, const Vector2d& size, double angle, double distance) {
  const Vector2d d(std::cos(angle), -std::sin(angle));
  const Vector2d anchor = centre + distance * d;
  // The box hangs off the anchor away from the ball: right of it when d points right, ...
  const Vector2d min(anchor.x() - size.x() * 0.5 * (1.0 - std::clamp(2.0 * d.x(), -1.0, 1.0)),
                     anchor.y() - size.y() * 0.5 * (1.0 - std::clamp(2.0 * d.y(), -1.0, 1.0)));
  return {min, min + size};
}

// Whether `box` meets the disc of `radius` about `centre`: its point nearest the centre is
// inside the disc.
bool MeetsDisc(const LabelBox& box, const Vector2d& centre, double radius) {
  const Vector2d nearest = centre.cwiseMax(box.min).cwiseMin(box.max);
  return (nearest - centre).norm() < radius;
}

// How much `box` covers of what is already there: placed labels, and the balls it meets (each
// counted by its bounding square, which grows with how deep the box reaches in).
double Cover(const LabelBox& box, const std::vector<LabelBox>& placed,
             const std::vector<Vector2d>& balls, double radius) {
  double area = 0.0;
  for (const LabelBox& p : placed) area += OverlapArea(box, p);
  const Vector2d half(radius, radius);
  for (const Vector2d& c : balls) {
    if (MeetsDisc(box, c, radius)) area += OverlapArea(box, {c - half, c + half});
  }
  return area;
}

}  // namespace

bool LabelBox::Overlaps(const LabelBox& o) const { return OverlapArea(*this, o) > 0.0; }

std::vector<LabelBox> PlaceLabels(const std::vector<LabelRequest>& labels, double radius,
                                  const std::vector<Vector2d>& other_balls) {
  std::vector<Vector2d> balls = other_balls;
  for (const LabelRequest& l : labels) balls.push_back(l.centre);
  std::vector<LabelBox> placed;
  for (const LabelRequest& l : labels) {
    LabelBox best;
    double least = std::numeric_limits<double>::infinity();
    for (int ring = 0; ring < kRings && least > 0.0; ++ring) {
      for (int k = 0; k < kDirections && least > 0.0; ++k) {
        const double angle = kPi / 4.0 + 2.0 * kPi * k / kDirections;  // upper right first
        const LabelBox box = BoxAt(l.centre, l.size, angle, radius + kGapPx + ring * kRingStepPx);
        const double cover = Cover(box, placed, balls, radius);
        if (cover < least) {
          least = cover;
          best = box;
        }
      }
    }
    placed.push_back(best);
  }
  return placed;
}

}  // namespace billiard::plot
