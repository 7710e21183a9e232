#include "sim/table/testing/degenerate_scenes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>

namespace billiard::table::testing {

using physics::BallState;
using physics::kVx;
using physics::kX;

namespace {

// A ball placed against a body is this much off it: within the rounding of its position, far
// inside the simulation's contact tolerance (1e-9 m), and never an overlap to refuse.
constexpr double kFrozen = 1e-15;  // [m]
constexpr int kPlacementTries = 50;
constexpr double kSlowest = 0.3, kFastest = 8.0;  // the cue ball's speed [m/s]
constexpr double kMostSideSpin = 60.0;            // [rad/s]
// Angles into or out of a cushion the cue ball runs along: square to it, and the grazing
// incidences at which a contact's polynomial loses its roots to rounding.
constexpr std::array<double, 6> kRailAngles{0.0, 1e-7, 1e-6, 3e-5, 1e-4, 1e-3};  // [rad]

Eigen::Vector2d Direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

bool Clear(const std::vector<SceneBall>& balls, const Eigen::Vector2d& p, double radius) {
  return std::all_of(balls.begin(), balls.end(), [&](const SceneBall& b) {
    return (b.state.segment<2>(kX) - p).norm() >= 2.0 * radius;
  });
}

// The draws of one scene, in a fixed order.
class Draws {
 public:
  explicit Draws(const Uniform& uniform) : uniform_(uniform) {}
  double Unit() { return std::clamp(uniform_(), 0.0, std::nextafter(1.0, 0.0)); }
  double Between(double lo, double hi) { return lo + (hi - lo) * Unit(); }
  int Below(int n) { return std::min(n - 1, static_cast<int>(n * Unit())); }

 private:
  const Uniform& uniform_;
};

// Where a ball goes: against a cushion (its index in `against`), against a ball before it, or
// anywhere on the surface; std::nullopt when no try finds room.
std::optional<Eigen::Vector2d> Place(const TableGeometry& table, double radius,
                                     const std::vector<SceneBall>& balls, Draws& draw,
                                     int* against) {
  for (int tries = 0; tries < kPlacementTries; ++tries) {
    const int kind = draw.Below(3);
    Eigen::Vector2d p;
    *against = -1;
    if (kind == 0) {
      const int k = draw.Below(static_cast<int>(table.lines.size()));
      const CushionLine& line = table.lines[k];
      p = line.a + draw.Between(0.05, 0.95) * (line.b - line.a) + (radius + kFrozen) * line.normal;
      *against = k;
    } else if (kind == 1 && !balls.empty()) {
      const SceneBall& next_to = balls[draw.Below(static_cast<int>(balls.size()))];
      p = next_to.state.segment<2>(kX) +
          (2.0 * radius + kFrozen) * Direction(draw.Between(0.0, 2.0 * M_PI));
    } else {
      p = {draw.Between(radius, table.length - radius), draw.Between(radius, table.width - radius)};
    }
    if (table.OnSurface(p, radius) && Clear(balls, p, radius)) return p;
  }
  return std::nullopt;
}

}  // namespace

std::vector<SceneBall> DegenerateScene(const TableGeometry& table, double radius,
                                       const Uniform& uniform) {
  Draws draw(uniform);
  const int count = 2 + draw.Below(7);
  std::vector<SceneBall> balls;
  int cue_against = -1;
  for (int id = 0; id < count; ++id) {
    int against = -1;
    const std::optional<Eigen::Vector2d> p = Place(table, radius, balls, draw, &against);
    if (!p) continue;
    if (id == 0) cue_against = against;
    SceneBall b;
    b.id = id;
    b.state.segment<2>(kX) = *p;
    balls.push_back(b);
  }
  if (balls.empty() || balls.front().id != 0) return balls;  // no room for a cue ball: all still

  // The cue ball's heading: along its cushion, at a ball's centre or edge, or anywhere.
  SceneBall& cue = balls.front();
  const Eigen::Vector2d from = cue.state.segment<2>(kX);
  double heading = draw.Between(-M_PI, M_PI);
  const int aim = draw.Below(3);
  if (aim == 0 && cue_against >= 0) {
    const CushionLine& line = table.lines[cue_against];
    const Eigen::Vector2d along = (draw.Unit() < 0.5 ? 1.0 : -1.0) * (line.b - line.a).normalized();
    const double into = kRailAngles[draw.Below(kRailAngles.size())] * (draw.Unit() < 0.5 ? 1 : -1);
    heading = std::atan2(along.y(), along.x()) -
              into * (along.x() * line.normal.y() - along.y() * line.normal.x() > 0 ? 1 : -1);
  } else if (aim == 1 && balls.size() > 1) {
    const SceneBall& target = balls[1 + draw.Below(static_cast<int>(balls.size()) - 1)];
    const Eigen::Vector2d to = target.state.segment<2>(kX) - from;
    // Full, or a cut up to the edge (a graze at the last of it).
    const double cut = std::asin(std::clamp(2.0 * radius * draw.Between(-1.0, 1.0) / to.norm(), -1.0, 1.0));
    heading = std::atan2(to.y(), to.x()) + (draw.Unit() < 0.25 ? 0.0 : cut);
  }
  const double speed = kSlowest * std::pow(kFastest / kSlowest, draw.Unit());
  const Eigen::Vector2d v = speed * Direction(heading);
  // Spin about the horizontal axis square to the heading, from draw (-1) through rolling (1)
  // to over-follow; side spin about z.
  const double roll = draw.Between(-1.0, 1.5) * speed / radius;
  cue.state.segment<2>(kVx) = v;
  cue.state[physics::kWx] = -roll * std::sin(heading);
  cue.state[physics::kWy] = roll * std::cos(heading);
  cue.state[physics::kWz] = draw.Between(-kMostSideSpin, kMostSideSpin);
  return balls;
}

TableSimulationOptions MotionOptions(const std::string& model, const physics::ModelParameters& p) {
  TableSimulationOptions options;
  if (model == "auto") {
    options.five_dof = [p](const BallState& s) {
      return FiveDofWhereNeeded(s, p, physics::SimulationOptions{});
    };
  } else if (model == "approx") {
    options.five_dof = [](const BallState&) {
      return std::optional<physics::SimulationOptions>(physics::SimulationOptions{});
    };
  } else if (model != "closed-form") {
    throw std::invalid_argument("no motion model '" + model + "' (closed-form, auto, approx)");
  }
  return options;
}

std::vector<SceneBall> SeededDegenerateScene(const TableGeometry& table, double radius,
                                             std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Uniform uniform = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  return DegenerateScene(table, radius, uniform);
}

SceneInvariants MeasureInvariants(const TableSimulation& sim, const TableGeometry& table,
                                  const physics::ModelParameters& p, double dt) {
  const double r = p.ball.radius;
  SceneInvariants out;
  double energy = INFINITY;
  const auto sample = [&](double t) {
    std::vector<Eigen::Vector2d> on_table;
    double e = 0.0;
    for (std::size_t i = 0; i < sim.ball_count(); ++i) {
      const BallState s = sim.StateAt(i, t);
      e += physics::KineticEnergy(s, p.ball.mass, r);
      const bool dropped = sim.pocket(i) && t >= sim.segments(i).back().start_time();
      if (dropped) continue;
      on_table.push_back(s.segment<2>(kX));
      // How far the ball is out of where a moving ball may be (over a pocket's mouth on its way to
      // drop included): r less the largest radius that fits where it is.
      if (!table.InsideBoundary(s.segment<2>(kX), r)) {
        double lo = 0.0, hi = r;
        for (int k = 0; k < 60; ++k) {
          const double mid = 0.5 * (lo + hi);
          (table.InsideBoundary(s.segment<2>(kX), mid) ? lo : hi) = mid;
        }
        out.off_surface = std::max(out.off_surface, r - lo);
      }
    }
    for (std::size_t i = 0; i < on_table.size(); ++i) {
      for (std::size_t j = i + 1; j < on_table.size(); ++j) {
        out.overlap = std::max(out.overlap, 2.0 * r - (on_table[i] - on_table[j]).norm());
      }
    }
    if (std::isfinite(energy) && energy > 0.0) {
      out.energy_rise = std::max(out.energy_rise, (e - energy) / energy);
    }
    energy = e;
  };
  for (double t = 0.0; t < sim.time(); t += dt) sample(t);
  sample(sim.time());
  return out;
}

}  // namespace billiard::table::testing
