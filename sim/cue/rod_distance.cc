#include "sim/cue/rod_distance.h"

#include <algorithm>
#include <cmath>

namespace billiard::cue {

namespace {

// The golden-section search stops when its bracket on the axis is this short [m].
constexpr double kAxisResolution = 1e-10;

// The least value of the convex `f` on [lo, hi] (golden-section search, Kiefer 1953), the ends
// included: where the least is at an end, the bracket closes on it from inside.
template <typename F>
double LeastOnSegment(const F& f, double lo, double hi) {
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  const double ends = std::min(f(lo), f(hi));
  double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
  double fa = f(a), fb = f(b);
  while (hi - lo > kAxisResolution) {
    if (fa < fb) {
      hi = b, b = a, fb = fa;
      a = hi - golden * (hi - lo), fa = f(a);
    } else {
      lo = a, a = b, fa = fb;
      b = lo + golden * (hi - lo), fb = f(b);
    }
  }
  return std::min({ends, fa, fb});
}

}  // namespace

double SignedDistance(const Eigen::Vector3d& p, const Box& box) {
  // Per axis, how far p lies beyond the box's slab (< 0 inside it).
  const Eigen::Vector3d beyond = (box.lower - p).cwiseMax(p - box.upper);
  const double outside = beyond.cwiseMax(0.0).norm();
  return outside > 0.0 ? outside : beyond.maxCoeff();
}

double DistanceToBall(const PlacedCue& cue, const Eigen::Vector3d& centre, double radius) {
  const Eigen::Vector3d to_centre = centre - cue.tip;
  const double along = to_centre.dot(cue.back);
  const double across = (to_centre - along * cue.back).norm();
  const double taper = cue.shape.Taper();
  const double nearest =
      std::clamp(along + taper * across / std::sqrt(1.0 - taper * taper), 0.0, cue.shape.length);
  return (cue.At(nearest) - centre).norm() - cue.shape.RadiusAt(nearest) - radius;
}

double DistanceToBox(const PlacedCue& cue, const Box& box) {
  return LeastOnSegment(
      [&](double s) { return SignedDistance(cue.At(s), box) - cue.shape.RadiusAt(s); }, 0.0,
      cue.shape.length);
}

}  // namespace billiard::cue
