#include "sim/cue/rod_distance.h"

#include <algorithm>
#include <cmath>

#include "sim/physics/golden_section.h"

namespace billiard::cue {

namespace {

// The golden-section search stops when its bracket on the axis is this short [m].
constexpr double kAxisResolution = 1e-10;

}  // namespace

double SignedDistance(const Eigen::Vector3d& p, const Box& box) {
  // Per axis, how far p lies beyond the box's slab (< 0 inside it).
  const Eigen::Vector3d beyond = (box.lower - p).cwiseMax(p - box.upper);
  const double outside = beyond.cwiseMax(0.0).norm();
  return outside > 0.0 ? outside : beyond.maxCoeff();
}

double DistanceToBall(const PlacedCue& cue, const Eigen::Vector3d& centre, double radius,
                      double* along) {
  const Eigen::Vector3d to_centre = centre - cue.tip;
  const double s_c = to_centre.dot(cue.back);
  const double across = (to_centre - s_c * cue.back).norm();
  const double taper = cue.shape.Taper();
  const double nearest =
      std::clamp(s_c + taper * across / std::sqrt(1.0 - taper * taper), 0.0, cue.shape.length);
  if (along) *along = nearest;
  return (cue.At(nearest) - centre).norm() - cue.shape.RadiusAt(nearest) - radius;
}

double DistanceToBox(const PlacedCue& cue, const Box& box, double* along) {
  const auto apart = [&](double s) {
    return SignedDistance(cue.At(s), box) - cue.shape.RadiusAt(s);
  };
  // Where the least is at an end, the bracket closes on it from inside.
  const double least = physics::GoldenSectionMinimum(
      apart, 0.0, cue.shape.length,
      [](double lo, double hi) { return hi - lo <= kAxisResolution; });
  double nearest = least;
  for (const double end : {0.0, cue.shape.length}) {
    if (apart(end) < apart(nearest)) nearest = end;
  }
  if (along) *along = nearest;
  return apart(nearest);
}

}  // namespace billiard::cue
