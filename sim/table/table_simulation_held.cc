// TableSimulation's held contacts (the bookkeeping beside the event loop of
// table_simulation.cc): the touching cluster gathered with its cushions and jaws, its contact
// forces solved (held_contacts.h: a complementarity problem, projected Gauss-Seidel), and the
// constant-acceleration motions those forces give, all ending with the first of them.
#include <algorithm>
#include <cmath>

#include "sim/table/contact_search.h"
#include "sim/table/held_contacts.h"
#include "sim/table/table_simulation.h"

namespace billiard::table {

using physics::BallState;
using physics::kVx;
using physics::kX;

namespace {

// A held motion whose forces do not act along the direction its cloth friction depends on (the
// slip's, sliding; the velocity's, rolling) turns that direction, which the motion takes as
// fixed: it is solved again this often. A head-on push, the common one, keeps its directions and
// is not cut.
constexpr double kHoldStep = 0.01;  // [s]
constexpr double kParallel = 1e-9;  // |sin| between two directions taken as one

}  // namespace

double TableSimulation::Gap(std::size_t i, std::size_t j) const {
  return (Current(i).At(time_).segment<2>(kX) - Current(j).At(time_).segment<2>(kX)).norm() -
         2.0 * params_.ball.radius;
}

std::vector<std::size_t> TableSimulation::HeldNeighbours(std::size_t i) const {
  std::vector<std::size_t> out;
  for (std::size_t j = 0; j < balls_.size(); ++j) {
    if (j != i && Active(j) && Current(j).held() && Gap(i, j) <= kHoldGap) out.push_back(j);
  }
  return out;
}

std::vector<std::size_t> TableSimulation::ResolveHeld(const std::vector<std::size_t>& seeds) {
  const double r = params_.ball.radius;
  // The cluster: every ball touching a seed, or a ball of the cluster, with the contacts between
  // them and with the cushions and jaws, in a fixed order.
  std::vector<std::size_t> members;
  std::vector<int> slot(balls_.size(), -1);
  for (const std::size_t i : seeds) {
    if (Active(i) && slot[i] < 0) {
      slot[i] = static_cast<int>(members.size());
      members.push_back(i);
    }
  }
  const std::size_t pressed = members.size();  // the seeds: the balls whose contact pressed
  std::vector<BallState> states;
  std::vector<HeldContact> contacts;
  std::vector<double> reach;  // per contact: the centres' distance that a part would grow
  const auto closes_slowly = [&](const Eigen::Vector2d& v, const Eigen::Vector2d& n) {
    return v.dot(n) <= kSlowImpact;
  };
  for (std::size_t m = 0; m < members.size(); ++m) {
    const std::size_t i = members[m];
    const BallState s = Current(i).At(time_);
    states.push_back(s);
    const Eigen::Vector2d p = s.segment<2>(kX);
    for (std::size_t j = 0; j < balls_.size(); ++j) {
      if (j == i || !Active(j) || (slot[j] >= 0 && slot[j] < static_cast<int>(m))) continue;
      const BallState t = Current(j).At(time_);
      const Eigen::Vector2d between = t.segment<2>(kX) - p;
      if (between.norm() - 2.0 * r > kHoldGap) continue;
      if (slot[j] < 0) {
        slot[j] = static_cast<int>(members.size());
        members.push_back(j);
      }
      const Eigen::Vector2d n = between.normalized();
      if (!closes_slowly(s.segment<2>(kVx) - t.segment<2>(kVx), n)) continue;  // an impact
      contacts.push_back({static_cast<int>(m), slot[j], n, 0.0});
      reach.push_back(2.0 * r);
    }
    for (const CushionLine& line : table_.lines) {
      const Eigen::Vector2d along = line.b - line.a;
      const double s_along = (p - line.a).dot(along) / along.squaredNorm();
      if (s_along < 0.0 || s_along > 1.0 || (p - line.a).dot(line.normal) - r > kHoldGap ||
          !closes_slowly(s.segment<2>(kVx), -line.normal)) {
        continue;
      }
      contacts.push_back({static_cast<int>(m), -1, -line.normal, params_.collision.cushion_friction});
      reach.push_back(kInfinity);  // along a straight cushion nothing parts
    }
    for (const CushionPoint& point : table_.points) {
      const Eigen::Vector2d to = point.centre - p;
      if (to.norm() - r - point.radius > kHoldGap || !closes_slowly(s.segment<2>(kVx), to.normalized())) {
        continue;
      }
      contacts.push_back({static_cast<int>(m), -1, to.normalized(), params_.collision.cushion_friction});
      reach.push_back(r + point.radius);
    }
  }
  const HeldSolution held = SolveHeldContacts(cloth_, states, contacts);

  // How long each ball's held motion holds: until a pressed contact parts by kHoldGap / 2 (its
  // normal is taken as fixed), a turning direction is due for a new solve, or what the solve
  // left closing would overlap by the contact tolerance.
  std::vector<double> longest(members.size(), kInfinity);
  if (held.residual > 0.0) {
    std::fill(longest.begin(), longest.end(), std::sqrt(2.0 * kContactTolerance / held.residual));
  }
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const HeldContact& c = contacts[k];
    if (held.normal_forces[k] == 0.0 || !std::isfinite(reach[k])) continue;
    const auto tangential = [&](Eigen::Vector2d x) { return x - x.dot(c.normal) * c.normal; };
    Eigen::Vector2d w = -held.states[c.a].segment<2>(kVx), alpha = -held.accelerations[c.a];
    if (c.b >= 0) {
      w += held.states[c.b].segment<2>(kVx);
      alpha += held.accelerations[c.b];
    }
    const double parts = SafeStep(std::sqrt(reach[k] * kHoldGap), tangential(w).norm(),
                                  tangential(alpha).norm());
    longest[c.a] = std::min(longest[c.a], parts);
    if (c.b >= 0) longest[c.b] = std::min(longest[c.b], parts);
  }
  // The held motions, all ending with the first of them: the end of one changes the forces of all.
  std::vector<std::optional<MotionSegment>> motion(members.size());
  double end = time_ + kFiveDofHorizon;
  for (std::size_t m = 0; m < members.size(); ++m) {
    if (held.forces[m].norm() == 0.0) continue;
    const BallState& s = held.states[m];
    const Eigen::Vector2d& a = held.accelerations[m];
    const Eigen::Vector2d drives =
        PhaseOf(s, r) == MotionPhase::kSliding ? ClothSlip(s, r) : Eigen::Vector2d(s.segment<2>(kVx));
    const double cross = drives.x() * a.y() - drives.y() * a.x();
    const bool turns = std::abs(cross) > kParallel * drives.norm() * a.norm();
    motion[m].emplace(cloth_, time_, s, a, turns ? std::min(longest[m], kHoldStep) : longest[m]);
    end = std::min(end, motion[m]->end_time());
  }
  std::vector<std::size_t> changed;
  for (std::size_t m = 0; m < members.size(); ++m) {
    const std::size_t i = members[m];
    const BallState& s = held.states[m];
    if (motion[m]) {
      // The first to end is already the motion; the others end with it.
      balls_[i].segments.push_back(
          motion[m]->end_time() <= end
              ? *motion[m]
              : MotionSegment(cloth_, time_, s, held.accelerations[m], end - time_));
    } else if (!Current(i).closed_form() && m < pressed) {
      // A 5-DOF ball that pressed into its contact where the closed form's cloth holds it off
      // (its own curve or slip): on by the closed form until its next event, or it would press
      // again at once, and again.
      balls_[i].segments.emplace_back(cloth_, time_, s);
    } else if (s != states[m] || Current(i).held()) {
      StartSegment(i, s);
    } else {
      continue;
    }
    changed.push_back(i);
  }
  return changed;
}

}  // namespace billiard::table
