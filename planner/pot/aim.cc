#include "planner/pot/aim.h"

#include <cmath>
#include <sstream>

#include "sim/table/ball_collision.h"

namespace billiard::pot {

using physics::BallState;

namespace {

// The cue ball's first contact at `*heading` where it is K; else at the nearest heading
// kContactStep apart, out to kContactScan either way, that meets K, `*heading` moved there.
std::optional<Contact> ContactWithK(SearchContext& search, const StrokeShape& shape, double* heading,
                                    bool truth) {
  Contact c = search.FirstContact(shape.At(*heading), truth);
  if (c.ball == search.object_id()) return c;
  for (double d = kContactStep; d <= kContactScan; d += kContactStep) {
    for (double sign : {1.0, -1.0}) {
      c = search.FirstContact(shape.At(*heading + sign * d), truth);
      if (c.ball == search.object_id()) {
        *heading += sign * d;
        return c;
      }
    }
  }
  return std::nullopt;
}

}  // namespace

double ThrowCorrectedNormal(const physics::ModelParameters& params, const Contact& c, double target) {
  const double r = params.ball.radius;
  const auto departure = [&](double normal) {
    BallState cue = c.cue_before;
    cue.head<2>() = c.object_at - 2.0 * r * Unit(normal);
    const table::BallBallImpulse hit =
        table::ResolveBallBallImpact(cue, c.object_before, params.ball, params.collision);
    return Angle(hit.b.segment<2>(physics::kVx));
  };
  double normal = target;
  for (int i = 0; i < 6; ++i) {
    const double f = Wrap(departure(normal) - target);
    if (std::abs(f) < 1e-12) break;
    const double h = 1e-7;
    const double slope = Wrap(departure(normal + h) - departure(normal - h)) / (2.0 * h);
    if (!(std::abs(slope) > 1e-6)) break;
    normal -= f / slope;
  }
  return normal;
}

std::optional<Aimed> AimAt(SearchContext& search, const StrokeShape& shape, double heading, double target,
                           bool truth, double slope, bool throw_corrected) {
  const int object = search.object_id();
  std::optional<Contact> met = ContactWithK(search, shape, &heading, truth);
  if (!met) return std::nullopt;
  Contact c = *met;
  const auto residual = [&](const Contact& x) {
    return Wrap((throw_corrected ? x.departure : x.normal) - target);
  };
  double f = residual(c);
  if (slope == 0.0) {
    const Contact probe = search.FirstContact(shape.At(heading + kAimProbe), truth);
    if (probe.ball != object) return std::nullopt;
    slope = Wrap(residual(probe) - f) / kAimProbe;
  }
  if (!std::isfinite(f) || !std::isfinite(slope)) return std::nullopt;
  // The impact model's step first: the normal that throws K onto the target, reached by
  // moving the contact along the cue ball's approach (the normal turns with the heading as
  // the departure does, less the throw's change).
  if (throw_corrected && std::abs(slope) > 0.0) {
    const double normal = ThrowCorrectedNormal(search.params(), c, target);
    const double normal_slope = slope;  // the throw changes slowly with the normal
    const double step = Wrap(normal - c.normal) / normal_slope;
    Contact next = search.FirstContact(shape.At(heading + step), truth);
    if (next.ball == object) {
      const double g = residual(next);
      if (std::abs(g) < std::abs(f)) {
        if (std::abs(g - f) > 0.0 && std::abs(step) > 0.0) slope = (g - f) / step;
        heading += step;
        c = next;
        f = g;
      }
    }
  }
  for (int i = 0; i < kMaxAimIterations && std::abs(f) > kAimTolerance; ++i) {
    if (!(std::abs(slope) > 1e-9) || !std::isfinite(slope)) return std::nullopt;
    double step = -f / slope;
    Contact next;
    double g = 0.0;
    for (int halving = 0; halving < 8; ++halving) {
      next = search.FirstContact(shape.At(heading + step), truth);
      if (next.ball == object) {
        g = residual(next);
        if (std::abs(g) < std::abs(f)) break;
      }
      step *= 0.5;
    }
    if (next.ball != object) return std::nullopt;
    if (std::abs(g - f) > 0.0) slope = (g - f) / step;
    heading += step;
    c = next;
    f = g;
  }
  if (!(std::abs(f) <= kAimAccepted) || !std::isfinite(heading)) return std::nullopt;
  return Aimed{heading, c, slope};
}

std::string BlockedReason(SearchContext& search, const StrokeShape& shape, double heading) {
  const Contact c = search.FirstContact(shape.At(heading), false);
  std::ostringstream s;
  if (c.ball >= 0 && c.ball != search.object_id()) {
    s << "the cue ball meets ball " << c.ball << " before ball " << search.object_id();
  } else {
    s << "no heading near the route meets ball " << search.object_id();
  }
  return s.str();
}

}  // namespace billiard::pot
