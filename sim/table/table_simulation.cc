#include "sim/table/table_simulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/table/ball_collision.h"
#include "sim/table/contact_search.h"

namespace billiard::table {

using physics::BallState;
using physics::kVx;
using physics::kWx;
using physics::kWz;
using physics::kX;

namespace {

// A sliding ball's 5-DOF motion runs until twice the closed form's slide time (at least
// kShortestHorizon), a rolling one's until kFiveDofHorizon.
constexpr double kSlideHorizonFactor = 2.0;
constexpr double kShortestHorizon = 0.05;  // [s]

// Two impacts of the same pair closer in time than this: the second is elastic (TC model).
constexpr double kCollapseTime = 1e-5;  // [s]

// The frame of a cushion whose normal `n` points into the playing area: x along the cushion,
// y into it, z up (right-handed: y is x turned by +90 degrees).
struct CushionFrame {
  Eigen::Vector2d x, y;
  explicit CushionFrame(const Eigen::Vector2d& n) : x(-n.y(), n.x()), y(-n) {}
  Eigen::Vector3d In(const Eigen::Vector2d& xy, double z) const {
    return {xy.dot(x), xy.dot(y), z};
  }
  Eigen::Vector2d Out(const Eigen::Vector3d& c) const { return c.x() * x + c.y() * y; }
};

}  // namespace

int FirstBallMet(const std::vector<TableEvent>& events, int id) {
  for (const TableEvent& e : events) {
    if (e.type == EventType::kBallBall && (e.ball == id || e.other == id)) {
      return e.ball == id ? e.other : e.ball;
    }
  }
  return -1;
}

bool SettlesFirstBallMet(const TableEvent& e, int id) {
  return (e.type == EventType::kBallBall && (e.ball == id || e.other == id)) ||
         (e.type == EventType::kBallPocket && e.ball == id);
}

const char* EventTypeName(EventType type) {
  switch (type) {
    case EventType::kTransition:
      return "transition";
    case EventType::kBallBall:
      return "ball_ball";
    case EventType::kBallCushion:
      return "ball_cushion";
    case EventType::kBallJaw:
      return "ball_jaw";
    case EventType::kBallPocket:
      return "ball_pocket";
    case EventType::kBallPush:
      return "ball_push";
  }
  return "unknown";
}

std::optional<physics::SimulationOptions> FiveDofWhereNeeded(
    const BallState& state, const physics::ModelParameters& params,
    const physics::SimulationOptions& options) {
  constexpr double kStraightSpin = 20.0;  // [rad/s]
  const bool rolling = ClothSlip(state, params.ball.radius).norm() <= kSlideSlip;
  if (rolling && std::abs(state[kWz]) <= kStraightSpin) return std::nullopt;
  return options;
}

TableSimulation::TableSimulation(const TableGeometry& table, const physics::ModelParameters& params,
                                 const std::vector<SceneBall>& balls,
                                 const TableSimulationOptions& options)
    : table_(table), params_(params), cloth_(ClothParameters::From(params)), options_(options) {
  physics::ValidateParameters(params);
  ValidateScene(table, params.ball.radius, balls);
  for (const SceneBall& b : balls) {
    balls_.push_back({b.id, {}, std::nullopt});
    StartSegment(balls_.size() - 1, b.state, b.flight);
  }
  boundary_.resize(balls_.size());
  pair_.assign(balls_.size() * balls_.size(), Candidate{});
  last_impact_.assign(balls_.size() * balls_.size(), -kInfinity);
  for (std::size_t i = 0; i < balls_.size(); ++i) Recompute(i);
}

std::size_t TableSimulation::PairIndex(std::size_t i, std::size_t j) const {
  return std::min(i, j) * balls_.size() + std::max(i, j);
}

bool TableSimulation::AtRest() const {
  for (std::size_t i = 0; i < balls_.size(); ++i) {
    if (Active(i) && Current(i).phase() != MotionPhase::kStationary) return false;
  }
  return true;
}

BallState TableSimulation::StateAt(std::size_t i, double t) const {
  const std::vector<MotionSegment>& s = balls_[i].segments;
  // The last segment that starts at or before t (a zero-length segment gives way to the next).
  auto it = std::upper_bound(s.begin(), s.end(), t, [](double time, const MotionSegment& m) {
    return time < m.start_time();
  });
  return (it == s.begin() ? s.front() : *(it - 1)).At(t);
}

TableSimulation::Candidate TableSimulation::NextBallBall(std::size_t i, std::size_t j) const {
  const MotionSegment& a = Current(i);
  const MotionSegment& b = Current(j);
  if (a.phase() == MotionPhase::kStationary && b.phase() == MotionPhase::kStationary) return {};
  if (!a.closed_form() || !b.closed_form()) return BallBallByAdvancement(i, j);
  const double window = std::min(a.end_time(), b.end_time()) - time_;
  const Parabola pa = ParabolaAt(a, time_);
  const Parabola pb = ParabolaAt(b, time_);
  const Parabola relative{pb.p - pa.p, pb.v - pa.v, pb.a - pa.a};
  // Cheap rejection: neither ball can cover the gap within the window.
  const double reach = [&] {
    const double w = std::min(window, 1e6);
    return (relative.v.norm() + 0.5 * relative.a.norm() * w) * w;
  }();
  const double gap = relative.p.norm() - 2.0 * params_.ball.radius;
  if (gap > reach + kContactTolerance) return {};
  const Quartic f = DistanceSquaredMinus(relative, 2.0 * params_.ball.radius);
  const double d = 2.0 * params_.ball.radius;
  return {time_ + FirstCrossing(f, window, -1.0, 2.0 * d * kContactTolerance, 2.0 * d,
                                [](double) { return true; }),
          EventType::kBallBall};
}

TableSimulation::Candidate TableSimulation::NextBoundary(std::size_t i) const {
  Candidate best;
  if (!Active(i) || Current(i).phase() == MotionPhase::kStationary ||
      Current(i).phase() == MotionPhase::kSpinning) {
    return best;
  }
  const MotionSegment& m = Current(i);
  if (!m.closed_form()) return BoundaryByAdvancement(i);
  const double window = m.end_time() - time_;
  const Parabola q = ParabolaAt(m, time_);
  const double r = params_.ball.radius;
  const auto consider = [&](double tau, EventType type, int index) {
    if (time_ + tau < best.time) best = {time_ + tau, type, index};
  };
  for (std::size_t k = 0; k < table_.lines.size(); ++k) {
    const CushionLine& line = table_.lines[k];
    const Eigen::Vector2d along = line.b - line.a;
    const double length2 = along.squaredNorm();
    const auto within = [&](double tau) {
      const double s = (PositionAt(q, tau) - line.a).dot(along);
      return s >= 0.0 && s <= length2;
    };
    consider(FirstCrossing(AlongMinus(q, line.a, line.normal, r), window, -1.0, kContactTolerance,
                           1.0, within),
             EventType::kBallCushion, static_cast<int>(k));
  }
  for (std::size_t k = 0; k < table_.points.size(); ++k) {
    const CushionPoint& point = table_.points[k];
    const Parabola relative{q.p - point.centre, q.v, q.a};
    const double d = r + point.radius;
    consider(FirstCrossing(DistanceSquaredMinus(relative, d), window, -1.0,
                           2.0 * d * kContactTolerance, 2.0 * d, [](double) { return true; }),
             EventType::kBallJaw, static_cast<int>(k));
  }
  for (std::size_t k = 0; k < table_.pockets.size(); ++k) {
    const Pocket& pocket = table_.pockets[k];
    const Eigen::Vector2d along = pocket.capture_b - pocket.capture_a;
    const auto within = [&](double tau) {
      const double s = (PositionAt(q, tau) - pocket.capture_a).dot(along);
      return s >= 0.0 && s <= along.squaredNorm();
    };
    consider(FirstCrossing(AlongMinus(q, pocket.capture_a, pocket.inward, 0.0), window, 1.0,
                           kContactTolerance, 1.0, within),
             EventType::kBallPocket, static_cast<int>(k));
  }
  return best;
}

TableSimulation::Candidate TableSimulation::BallBallByAdvancement(std::size_t i,
                                                                  std::size_t j) const {
  const MotionSegment& a = Current(i);
  const MotionSegment& b = Current(j);
  const double end = std::min(a.end_time(), b.end_time());
  const double d = 2.0 * params_.ball.radius;
  const double accel = a.max_acceleration() + b.max_acceleration();
  const auto clearance = [&](double t) {
    const BallState sa = a.At(t), sb = b.At(t);
    const Eigen::Vector2d between = sb.segment<2>(kX) - sa.segment<2>(kX);
    const double distance = between.norm();
    return Clearance{distance - d,
                     (sa.segment<2>(kVx) - sb.segment<2>(kVx)).dot(between) / distance,
                     EventType::kBallBall, -1};
  };
  const auto element = [&](double t, const Clearance&) { return clearance(t); };
  const Advancement found = FirstContactByAdvancement(clearance, element, accel, time_, end);
  return {found.time, EventType::kBallBall, -1, found.resume};
}

TableSimulation::Candidate TableSimulation::BoundaryByAdvancement(std::size_t i) const {
  const MotionSegment& m = Current(i);
  const double accel = m.max_acceleration();
  const auto clearance = [&](double t) {
    return BoundaryClearance(table_, params_.ball.radius, m.At(t), accel);
  };
  const auto element = [&](double t, const Clearance& c) {
    return ElementClearance(table_, params_.ball.radius, m.At(t), c.type, c.index);
  };
  const Advancement found =
      FirstContactByAdvancement(clearance, element, accel, time_, m.end_time());
  return {found.time, found.at.type, found.at.index, found.resume};
}

void TableSimulation::Recompute(std::size_t i) {
  boundary_[i] = NextBoundary(i);
  for (std::size_t j = 0; j < balls_.size(); ++j) {
    if (j == i) continue;
    const bool both = Active(i) && Active(j);
    pair_[PairIndex(i, j)] = both ? NextBallBall(i, j) : Candidate{};
  }
}

void TableSimulation::StartSegment(std::size_t i, const BallState& state,
                                   const physics::Flight& flight) {
  if (physics::Airborne(flight, params_.ball.gravity)) {
    balls_[i].segments.emplace_back(cloth_, time_, state, flight);
    return;
  }
  const bool moving =
      state.segment<2>(kVx).norm() > 0.0 || ClothSlip(state, params_.ball.radius).norm() > 0.0;
  const std::optional<physics::SimulationOptions> five_dof =
      moving && options_.five_dof ? options_.five_dof(state) : std::nullopt;
  if (five_dof) {
    // A sliding ball's 5-DOF motion is asked again once its slide should be over (the closed
    // form's slide time, with a margin for the rolling resistance that lengthens it), so that a
    // ball rolling on can change to the closed form.
    const MotionSegment closed(cloth_, time_, state);
    const bool slides = ClothSlip(state, params_.ball.radius).norm() > kSlideSlip;
    const double horizon = slides ? std::clamp(kSlideHorizonFactor * (closed.end_time() - time_),
                                               kShortestHorizon, kFiveDofHorizon)
                                  : kFiveDofHorizon;
    balls_[i].segments.emplace_back(params_, *five_dof, time_, state, horizon);
  } else {
    balls_[i].segments.emplace_back(cloth_, time_, state);
  }
}

BallState TableSimulation::CushionImpact(const BallState& s, const Eigen::Vector2d& normal,
                                         double height, double* impulse) const {
  const CushionFrame frame(normal);
  const ImpactVelocities before{frame.In(s.segment<2>(kVx), 0.0),
                                frame.In(s.segment<2>(kWx), s[kWz])};
  // A ball in the air meets the nose lower on itself by its height (no lower than its equator,
  // where the cushion models end: a ball that high is beyond any hop a planner plays).
  const double nose = std::max(table_.cushion_height - height, params_.ball.radius);
  const CushionParameters cushion{nose, params_.collision.cushion_restitution,
                                  params_.collision.cushion_friction, params_.contact.mu};
  const ImpactVelocities after =
      ResolveCushionImpact(options_.cushion_model, before, params_.ball, cushion,
                           options_.mathavan_steps);
  *impulse = params_.ball.mass * (before.v.y() - after.v.y());
  BallState out = s;
  out.segment<2>(kVx) = frame.Out(after.v);
  out.segment<2>(kWx) = frame.Out(after.w);
  out[kWz] = after.w.z();
  return out;
}

void TableSimulation::Apply(const TableEvent& e, std::size_t i, std::size_t j, int index) {
  TableEvent event = e;
  const BallState s = Current(i).At(time_);
  // An impact in the air leaves the flight as it was (the contacts are taken as in the plane).
  const physics::Flight flight = Current(i).FlightAt(time_);
  std::vector<std::size_t> changed{i};
  // The held balls whose forces counted on a ball that an impact or a pocket takes.
  std::vector<std::size_t> released;
  const auto release = [&](std::size_t k) {
    for (const std::size_t n : HeldNeighbours(k)) released.push_back(n);
  };
  switch (e.type) {
    case EventType::kBallPush:  // an outcome of the contact events, never a candidate
    case EventType::kTransition:
      event.from = Current(i).phase();
      if (Current(i).held()) {
        event.type = EventType::kBallPush;
        changed = ResolveHeld({i});
      } else if (Current(i).phase() == MotionPhase::kAirborne) {
        const physics::Landing landing = physics::LandOnBed(s, -flight.vertical_speed, params_);
        StartSegment(i, landing.state, landing.rebound);
      } else {
        StartSegment(i, s);
      }
      event.to = Current(i).phase();
      break;
    case EventType::kBallBall: {
      const BallState b = Current(j).At(time_);
      const Eigen::Vector2d n = (b.segment<2>(kX) - s.segment<2>(kX)).normalized();
      if ((s.segment<2>(kVx) - b.segment<2>(kVx)).dot(n) <= kSlowImpact) {
        event.type = EventType::kBallPush;
        changed = ResolveHeld({i, j});
        break;
      }
      release(i);
      release(j);
      // Impacts of one pair in quick succession are elastic (the "TC model" of Luding and
      // McNamara 1998): inelastic ones would shrink the gaps between them geometrically, an
      // infinity of impacts in a finite time (inelastic collapse) where a ball is driven into
      // another it carries along.
      physics::CollisionParameters collision = params_.collision;
      double& last = last_impact_[PairIndex(i, j)];
      if (time_ - last < kCollapseTime) collision.ball_restitution = 1.0;
      last = time_;
      const BallBallImpulse hit = ResolveBallBallImpact(s, b, params_.ball, collision);
      event.impulse = hit.normal;
      StartSegment(i, hit.a, flight);
      StartSegment(j, hit.b, Current(j).FlightAt(time_));
      changed.push_back(j);
      break;
    }
    case EventType::kBallCushion:
    case EventType::kBallJaw: {
      const Eigen::Vector2d n = e.type == EventType::kBallCushion
                                    ? table_.lines[index].normal
                                    : (s.segment<2>(kX) - table_.points[index].centre).normalized();
      if (-s.segment<2>(kVx).dot(n) <= kSlowImpact) {
        event.type = EventType::kBallPush;
        changed = ResolveHeld({i});
      } else {
        release(i);
        StartSegment(i, CushionImpact(s, n, flight.height, &event.impulse), flight);
      }
      break;
    }
    case EventType::kBallPocket: {
      release(i);
      BallState dropped = s;
      dropped.segment<5>(kVx).setZero();
      StartSegment(i, dropped);
      balls_[i].pocket = table_.pockets[index].name;
      event.pocket = *balls_[i].pocket;
      break;
    }
  }
  events_.push_back(event);
  // The event's own balls are searched again even when nothing of theirs changed: their
  // candidate is the event just met.
  for (const std::size_t k : {i, j}) {
    if (k < balls_.size() && std::find(changed.begin(), changed.end(), k) == changed.end()) {
      changed.push_back(k);
    }
  }
  for (const std::size_t k : changed) Recompute(k);
  if (!released.empty()) {
    TableEvent push;
    push.time = time_;
    push.type = EventType::kBallPush;
    push.ball = balls_[released.front()].id;
    events_.push_back(push);
    for (const std::size_t k : ResolveHeld(released)) Recompute(k);
  }
}

void TableSimulation::Run(double t_end) { RunUntil(nullptr, t_end); }

bool TableSimulation::RunUntil(const std::function<bool(const TableEvent&)>& stop, double t_end) {
  if (!(t_end >= time_)) throw std::invalid_argument("the end time is before the present");
  while (true) {
    // The earliest candidate; ties to the lower index and the kinds in declaration order.
    double best = kInfinity;
    TableEvent next;
    std::size_t bi = 0, bj = 0;
    int index = -1;
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      if (!Active(i)) continue;
      if (Current(i).end_time() < best) {
        best = Current(i).end_time();
        next.type = EventType::kTransition;
        bi = i;
      }
    }
    bool resume = false;
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      for (std::size_t j = i + 1; j < balls_.size(); ++j) {
        if (pair_[PairIndex(i, j)].time < best) {
          best = pair_[PairIndex(i, j)].time;
          next.type = EventType::kBallBall;
          resume = pair_[PairIndex(i, j)].resume;
          bi = i;
          bj = j;
        }
      }
    }
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      if (boundary_[i].time < best) {
        best = boundary_[i].time;
        next.type = boundary_[i].type;
        resume = boundary_[i].resume;
        bi = i;
        index = boundary_[i].index;
      }
    }
    if (best > t_end || best == kInfinity) break;  // the end, or everything at rest
    if (resume) {  // a search by advancement goes on from where it stopped
      time_ = best;
      if (next.type == EventType::kBallBall) {
        pair_[PairIndex(bi, bj)] = NextBallBall(bi, bj);
      } else {
        boundary_[bi] = NextBoundary(bi);
      }
      continue;
    }
    if (static_cast<std::int64_t>(events_.size()) >= options_.max_events) {
      throw std::runtime_error("the scene needs more than " + std::to_string(options_.max_events) +
                               " events");
    }
    time_ = best;
    next.time = best;
    next.ball = balls_[bi].id;
    if (next.type == EventType::kBallBall) {
      next.other = balls_[bj].id;
    } else {
      bj = balls_.size();  // no other ball
    }
    if (next.type == EventType::kBallCushion || next.type == EventType::kBallJaw) {
      next.cushion = index;
    }
    const std::size_t before = events_.size();
    Apply(next, bi, bj, index);
    if (stop && std::any_of(events_.begin() + static_cast<std::ptrdiff_t>(before), events_.end(),
                            stop)) {
      return true;
    }
  }
  if (std::isfinite(t_end)) time_ = t_end;
  return false;
}

}  // namespace billiard::table
