#include "planner/pot/lone_path.h"

#include <cmath>
#include <memory>
#include <vector>

#include "planner/pot/aim.h"
#include "planner/pot/drop_window.h"
#include "planner/pot/pot_geometry.h"

namespace billiard::pot {

using physics::BallState;
using table::EventType;
using table::SceneBall;
using table::TableSimulation;

namespace {

// The longest a cue ball's path is followed to find where it passes its ghost ball [s].
constexpr double kLongestTime = 10.0;
// How far a curve's cut on its path alone may lie beyond the cue's limit and its aim still be
// searched: the aim moves the contact around the object ball, which turns the cut [rad].
constexpr double kCurveCutSlack = 10.0 * kDegree;

}  // namespace

Passing Pass(SearchContext& search, const SceneBall& ball, const Eigen::Vector2d& point,
             bool after_rail) {
  std::vector<SceneBall> alone = {ball};
  std::unique_ptr<TableSimulation> sim = search.Simulation(alone, false);
  // Run a stretch at a time until the path has passed the point (it draws away again) or
  // the ball rests: a kick's cue ball would go on from cushion to cushion.
  constexpr double kStretch = 0.1, kSample = 2e-3;  // [s]
  constexpr double kPassed = 0.2;                    // [m] beyond the closest approach
  double best = std::numeric_limits<double>::infinity(), t = 0.0;
  Passing passing;
  bool railed = !after_rail;
  std::size_t seen = 0;
  while (!sim->AtRest() && t < kLongestTime) {
    sim->Run(t + kStretch);
    for (; seen < sim->events().size(); ++seen) {
      if (sim->events()[seen].type == EventType::kBallCushion && !railed) {
        railed = true;
        t = sim->events()[seen].time;
      }
    }
    if (!railed) {
      t = sim->time();
      continue;
    }
    double d = best;
    for (; t <= sim->time(); t += kSample) {
      const BallState s = sim->StateAt(0, t);
      const Eigen::Vector2d to = point - s.head<2>();
      d = to.norm();
      if (d < best) {
        best = d;
        const Eigen::Vector2d v = s.segment<2>(physics::kVx);
        passing = {(v.x() * to.y() - v.y() * to.x()) > 0.0 ? best : -best, v};
      }
    }
    if (d > best + kPassed) break;
  }
  return railed ? passing : Passing{};
}

double PassingSide(SearchContext& search, const physics::CueStroke& stroke, const Eigen::Vector2d& point,
                   bool after_rail) {
  return Pass(search, table::Struck(0, stroke, search.cue_position(), search.params()), point,
              after_rail)
      .side;
}

double PassingSide(SearchContext& search, const BallState& state, const Eigen::Vector2d& point, bool after_rail) {
  return Pass(search, SceneBall{0, state}, point, after_rail).side;
}

double FirstHeading(SearchContext& search, const Route& route, const StrokeShape& shape,
                    const Eigen::Vector2d& ghost) {
  const Eigen::Vector2d to = route.kind == ShotKind::kKick ? route.cue_aim : ghost;
  double heading = Angle(to - search.cue_position());
  if (route.kind == ShotKind::kDirect || route.kind == ShotKind::kBank) {
    if (route.tip_side != 0.0) heading -= physics::SquirtAngle(route.tip_side, search.params());
    return heading;
  }
  const bool kick = route.kind == ShotKind::kKick;
  double h0 = heading, f0 = PassingSide(search, shape.At(h0), ghost, kick);
  double h1 = h0 + kAimProbe, f1 = PassingSide(search, shape.At(h1), ghost, kick);
  if (!std::isfinite(f0) || !std::isfinite(f1)) return heading;
  for (int i = 0; i < kMaxAimIterations && std::abs(f1) > 1e-5 && f1 != f0; ++i) {
    const double h2 = h1 - f1 * (h1 - h0) / (f1 - f0);
    h0 = h1;
    f0 = f1;
    h1 = h2;
    f1 = PassingSide(search, shape.At(h1), ghost, kick);
    if (!std::isfinite(f1)) return heading;
  }
  return h1;
}

std::optional<Refusal> CurveTooThin(SearchContext& search, const StrokeShape& shape, double heading,
                                    const Eigen::Vector2d& ghost, const Eigen::Vector2d& departure) {
  const Passing pass =
      Pass(search, table::Struck(0, shape.At(heading), search.cue_position(), search.params()),
           ghost, false);
  if (!(std::abs(pass.side) < search.radius()) || pass.velocity.norm() <= 0.0) return std::nullopt;
  const double cut = CutAngle(pass.velocity.normalized(), departure);
  const double limit = search.options().max_cut_deg * kDegree;
  if (cut <= limit + kCurveCutSlack) return std::nullopt;
  return Refusal{PotStatus::kTooThin, "the curve's cut is " + Degrees(cut) + ", beyond " + Degrees(limit)};
}

double BankLine(SearchContext& search, const Contact& c, double mirror) {
  const double scale = ReachScale(c);
  const auto side = [&](double direction) {
    BallState k = Rotated(c.object_after, Wrap(direction - c.departure));
    k.tail<5>() *= scale;
    return PassingSide(search, k, search.pocket().centre, true);
  };
  double h0 = mirror, f0 = side(h0), h1 = h0 + kAimProbe, f1 = side(h1);
  for (int i = 0; i < kMaxAimIterations && std::isfinite(f0) && std::isfinite(f1) &&
                  std::abs(f1) > 1e-4 && f1 != f0; ++i) {
    const double h2 = h1 - f1 * (h1 - h0) / (f1 - f0);
    h0 = h1;
    f0 = f1;
    h1 = h2;
    f1 = side(h1);
  }
  return std::isfinite(f1) && std::abs(Wrap(h1 - mirror)) < kRailScan ? h1 : mirror;
}

}  // namespace billiard::pot
