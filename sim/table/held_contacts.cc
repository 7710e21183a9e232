#include "sim/table/held_contacts.h"

#include <algorithm>
#include <cmath>

namespace billiard::table {

using physics::BallState;
using physics::kVx;
using physics::kWx;
using physics::kWy;

namespace {

// A solid sphere rolling under a force through its centre: m / (m + I / r^2).
constexpr double kRollingMobility = 5.0 / 7.0;

// The solves stop when no contact's closing speed or acceleration changes by more than this in
// a sweep: held over a second, such a residue moves the bodies by a picometre.
constexpr double kSpeedTolerance = 1e-12;  // [m/s]
constexpr double kAccelerationTolerance = 1e-12;  // [m/s^2]
// Sweeps before a solve gives up and returns what it has (its residual says how far off): a
// chain of n balls converges in a few times n^2 sweeps.
constexpr int kMaxSweeps = 10000;

// A rolling ball of a held cluster slower than this is at rest: its rolling resistance stops it
// within 1.5 ms, over 0.1 um. Met as rolling, a cluster coming to rest would be solved again at
// every least speed of each ball, as the contact forces turn their velocities, ever more often.
constexpr double kRestSpeed = 1e-4;  // [m/s]

// Touching bodies parting faster than this are left alone. Parting slower, their accelerations
// (a few m/s^2 at most) could turn them within the event search's kContactHorizon (1e-6 s),
// which takes that for closing now: the solve stops their parting and holds them.
constexpr double kParting = 1e-5;  // [m/s]

// How one ball's centre answers a force through it, per unit mass.
struct Response {
  double mobility = 1.0;
  Eigen::Vector2d drift = Eigen::Vector2d::Zero();  // the acceleration without the force
  double threshold = 0.0;  // at rest: the force's effect that the rolling resistance holds

  Eigen::Vector2d Acceleration(const Eigen::Vector2d& force) const {
    if (threshold == 0.0) return drift + mobility * force;
    const double f = force.norm();
    if (mobility * f <= threshold) return Eigen::Vector2d::Zero();
    return (mobility - threshold / f) * force;
  }
};

Response ResponseOf(const ClothParameters& cloth, const BallState& s) {
  const double rolling_decel = kRollingMobility * cloth.mu_roll * cloth.gravity;
  switch (PhaseOf(s, cloth.radius)) {
    case MotionPhase::kSliding:
      return {1.0, -cloth.mu_slide * cloth.gravity * ClothSlip(s, cloth.radius).normalized(), 0.0};
    case MotionPhase::kRolling:
      return {kRollingMobility, -rolling_decel * s.segment<2>(kVx).normalized(), 0.0};
    default:
      return {kRollingMobility, Eigen::Vector2d::Zero(), rolling_decel};
  }
}

// A ball that rolls: w_xy from v.
void RollOn(BallState* s, double radius) {
  (*s)[kWx] = -(*s)[physics::kVy] / radius;
  (*s)[kWy] = (*s)[kVx] / radius;
}

// The velocity change of a ball of `mobility` by an impulse per unit mass `j`; a ball that rolls
// (or rests) rolls on.
void Kick(BallState* s, const Eigen::Vector2d& j, double mobility, double radius) {
  s->segment<2>(kVx) += mobility * j;
  if (mobility != 1.0) RollOn(s, radius);
}

}  // namespace

HeldSolution SolveHeldContacts(const ClothParameters& cloth, std::vector<BallState> states,
                               const std::vector<HeldContact>& contacts) {
  const std::size_t n = states.size();
  HeldSolution out;
  for (BallState& s : states) {
    // A slip within the 5-DOF contact's residue is rolling: the state its slide would end in
    // within 0.15 ms, with the energy the slide loses (v - 2/7 u: Jaroukh 2019, eq. 6 at the
    // slide's end, eq. 8).
    const Eigen::Vector2d u = ClothSlip(s, cloth.radius);
    if (u.norm() <= kSlideSlip) {
      s.segment<2>(kVx) -= 2.0 / 7.0 * u;
      RollOn(&s, cloth.radius);
    }
    if (PhaseOf(s, cloth.radius) != MotionPhase::kSliding && s.segment<2>(kVx).norm() < kRestSpeed) {
      s.segment<4>(kVx).setZero();
    }
  }
  // Slow closings meet plastically, and slow partings are stopped (a held contact starts with
  // its bodies moving together along its normal, so that its force does no work): impulses
  // that leave no such contact closing or parting.
  // A ball at rest takes no part in it (a push slower than kSlowImpact stops against it, and
  // the forces then decide whether it moves): kicked to a crawl, it would crawl on.
  std::vector<double> mobility(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Response r = ResponseOf(cloth, states[i]);
    mobility[i] = r.threshold > 0.0 ? 0.0 : r.mobility;
  }
  const auto closing_speed = [&](const HeldContact& c) {
    const Eigen::Vector2d vb =
        c.b >= 0 ? Eigen::Vector2d(states[c.b].segment<2>(kVx)) : Eigen::Vector2d::Zero();
    return (states[c.a].segment<2>(kVx) - vb).dot(c.normal);
  };
  const auto pair_mobility = [&](const HeldContact& c) {
    return mobility[c.a] + (c.b >= 0 ? mobility[c.b] : 0.0);
  };
  std::vector<bool> pressing(contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    pressing[k] = closing_speed(contacts[k]) >= -kParting;
  }
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    double change = 0.0;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      if (!pressing[k]) continue;
      const HeldContact& c = contacts[k];
      if (pair_mobility(c) == 0.0) continue;
      const double delta = closing_speed(c) / pair_mobility(c);
      if (delta == 0.0) continue;
      Kick(&states[c.a], -delta * c.normal, mobility[c.a], cloth.radius);
      if (c.b >= 0) Kick(&states[c.b], delta * c.normal, mobility[c.b], cloth.radius);
      change = std::max(change, std::abs(delta) * pair_mobility(c));
    }
    if (change <= kSpeedTolerance) break;
  }

  // The forces that keep the contacts that do not part from closing.
  std::vector<Response> response(n);
  for (std::size_t i = 0; i < n; ++i) {
    response[i] = ResponseOf(cloth, states[i]);
    mobility[i] = response[i].mobility;
  }
  std::vector<Eigen::Vector2d> push(contacts.size());  // the force on a per unit normal force
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const HeldContact& c = contacts[k];
    push[k] = -c.normal;
    if (c.b < 0 && c.friction > 0.0) {  // a cushion's friction against the sliding along it
      const Eigen::Vector2d v = states[c.a].segment<2>(kVx);
      const Eigen::Vector2d along = v - v.dot(c.normal) * c.normal;
      if (along.norm() > kRestSpeed) push[k] -= c.friction * along.normalized();
    }
  }
  std::vector<Eigen::Vector2d> force(n, Eigen::Vector2d::Zero());
  std::vector<double> normal(contacts.size(), 0.0);
  const auto closing_acceleration = [&](const HeldContact& c) {
    const Eigen::Vector2d aa = response[c.a].Acceleration(force[c.a]);
    const Eigen::Vector2d ab =
        c.b >= 0 ? response[c.b].Acceleration(force[c.b]) : Eigen::Vector2d::Zero();
    return (aa - ab).dot(c.normal);
  };
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    double change = 0.0;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      if (!pressing[k]) continue;
      const HeldContact& c = contacts[k];
      const double next = std::max(0.0, normal[k] + closing_acceleration(c) / pair_mobility(c));
      const double delta = next - normal[k];
      if (delta == 0.0) continue;
      normal[k] = next;
      force[c.a] += delta * push[k];
      if (c.b >= 0) force[c.b] += delta * c.normal;
      change = std::max(change, std::abs(delta) * pair_mobility(c));
    }
    if (change <= kAccelerationTolerance) break;
  }
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    if (pressing[k]) out.residual = std::max(out.residual, closing_acceleration(contacts[k]));
  }
  out.accelerations.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.accelerations[i] = response[i].Acceleration(force[i]);
  out.states = std::move(states);
  out.forces = std::move(force);
  out.normal_forces = std::move(normal);
  return out;
}

}  // namespace billiard::table
