// Issue 47's acceptance: no stroke the planner commands passes a real cue through a ball, the
// cloth or a rail. Checked by a rod written here from the geometry alone, apart from sim/cue's
// closed forms and golden-section search and from the planner: points every millimetre along
// the cue's axis, each a sphere of the cue's radius there, against every other ball (a sphere),
// the cloth over the playing surface (z = 0) and the four rails (bands from the nose lines
// outward by the rail's width, up to the rail's height).
//
// Over 1,000 seeded pots (plan-pot's PlanPot, every kind, with the gantry robot) on layouts moved
// to be hard for a cue: a third with the cue ball within 8 cm of a rail, a quarter with it within
// 5 radii of another ball; and over 24 full choices (ChooseShot, any ball) the same way. The
// elevations and the refusals are printed.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <vector>

#include "planner/choice/shot_choice.h"
#include "planner/pot/pot_planner.h"
#include "planner/pot/testing/pot_layouts.h"
#include "sim/batch/thread_pool.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"
#include "sim/table/seeded_uniform.h"
#include "sim/table/table_simulation.h"

namespace billiard {
namespace {

constexpr double kSampleStep = 1e-3;  // along the cue's axis [m]
constexpr double kNearRail = 0.08;    // a third of the cue balls within this of a rail [m]
constexpr double kNearBallRadii = 5;  // a quarter within this many radii of another ball

// The least gap [m] between the sampled rod of `robot`'s cue for `stroke` on the cue ball (id 0)
// and the other balls, the cloth and the rails of `table`: < 0 where the cue passes through.
double SampledGap(const table::TableGeometry& table, double radius, const std::vector<table::SceneBall>& balls,
                  const physics::CueStroke& stroke, const cue::Robot& robot, std::string* what) {
  const double ch = std::cos(stroke.heading), sh = std::sin(stroke.heading);
  const double ce = std::cos(stroke.elevation), se = std::sin(stroke.elevation);
  const Eigen::Vector3d c(ce * ch, ce * sh, -se);   // the cue's axis, forward and down
  const Eigen::Vector3d n(sh, -ch, 0.0);            // its horizontal right
  const Eigen::Vector3d u = n.cross(c);             // its up
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const table::SceneBall& b : balls) {
    if (b.id == 0) centre = {b.state.x(), b.state.y(), radius};
  }
  // The tip where the offsets put it on the ball's surface.
  const Eigen::Vector3d offset = stroke.tip_side * n + stroke.tip_height * u;
  const Eigen::Vector3d tip = centre + offset - std::sqrt(radius * radius - offset.squaredNorm()) * c;
  double gap = 1e9;
  const auto note = [&](double g, const std::string& name) {
    if (g < gap) {
      gap = g;
      *what = name;
    }
  };
  for (double s = 0.0; s <= robot.cue.length + 1e-12; s += kSampleStep) {
    const Eigen::Vector3d p = tip - s * c;
    const double r = robot.cue.tip_radius + (robot.cue.butt_radius - robot.cue.tip_radius) * s / robot.cue.length;
    for (const table::SceneBall& b : balls) {
      if (b.id == 0) continue;
      note((p - Eigen::Vector3d(b.state.x(), b.state.y(), radius)).norm() - radius - r, "ball " + std::to_string(b.id));
    }
    const bool over_surface = p.x() >= 0 && p.x() <= table.length && p.y() >= 0 && p.y() <= table.width;
    if (over_surface) note(p.z() - r, "the cloth");
    // A rail band: outward of a nose line by up to the rail's width, below the rail's height.
    const double w = table.rail_width, h = table.rail_height;
    const auto band = [&](double out, double along, double along_max, const std::string& name) {
      // `out`: how far beyond the nose line; `along`: the position along the rail.
      const double dx = std::max({-out, out - w, 0.0});
      const double dy = std::max({-along - w, along - along_max - w, 0.0});
      const double dz = std::max(p.z() - h, 0.0);
      const bool inside = dx == 0 && dy == 0 && dz == 0;
      const double outside = std::sqrt(dx * dx + dy * dy + dz * dz);
      note(inside ? -std::min({out, w - out, h - p.z()}) - r : outside - r, name);
    };
    band(-p.y(), p.x(), table.length, "the lower rail");
    band(p.y() - table.width, p.x(), table.length, "the upper rail");
    band(-p.x(), p.y(), table.width, "the left rail");
    band(p.x() - table.length, p.y(), table.width, "the right rail");
  }
  return gap;
}

// The layout of `seed` with its cue ball moved, for `case_index`, within kNearRail of a rail (a
// third), within kNearBallRadii radii of another ball (a quarter), or left where it was; a move
// tried until the scene is valid.
std::vector<table::SceneBall> HardLayout(const table::TableGeometry& table, double radius, std::uint64_t seed,
                                         int case_index, const std::vector<table::SceneBall>& balls) {
  table::SeededUniform random(seed * 7919 + 13);
  const bool near_rail = case_index % 3 == 0, near_ball = case_index % 4 == 1;
  if (!near_rail && !near_ball) return balls;
  for (int attempt = 0; attempt < 200; ++attempt) {
    std::vector<table::SceneBall> moved = balls;
    Eigen::Vector2d at;
    if (near_rail) {
      const double gap = random.Between(0.0, kNearRail);
      at = {random.Between(radius, table.length - radius), random.Between(radius, table.width - radius)};
      switch (random.Below(4)) {
        case 0: at.y() = radius + gap; break;
        case 1: at.y() = table.width - radius - gap; break;
        case 2: at.x() = radius + gap; break;
        default: at.x() = table.length - radius - gap; break;
      }
    } else {
      const table::SceneBall& other = balls[1 + random.Below(balls.size() - 1)];
      const double d = random.Between(2.0 * radius, kNearBallRadii * radius), a = random.Between(0.0, 2.0 * M_PI);
      at = other.state.head<2>() + d * Eigen::Vector2d(std::cos(a), std::sin(a));
    }
    moved[0].state.head<2>() = at;
    try {
      table::ValidateScene(table, radius, moved);
      if (table.OnSurface(at, radius)) return moved;
    } catch (const std::invalid_argument&) {
    }
  }
  return balls;
}

double Quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * (v.size() - 1))];
}

TEST(CueClearanceAcceptance, NoPlannedPotPassesTheCueThroughABallTheClothOrARail) {
  const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const physics::ModelParameters params = params::LoadParameters("pool");
  const double radius = params.ball.radius;
  pot::PotOptions options;
  options.robot = params::LoadRobot("gantry");
  std::vector<double> elevations;
  std::map<std::string, int> statuses;
  int ok = 0, elevated = 0, lifts = 0;
  for (int i = 0; i < 1000; ++i) {
    const std::uint64_t seed = 47000 + static_cast<std::uint64_t>(i);
    pot::testing::PotLayout layout = pot::testing::SeededPotLayout(table, radius, seed);
    const std::vector<table::SceneBall> balls = HardLayout(table, radius, seed, i, layout.balls);
    const pot::PotPlan plan = pot::PlanPot(table, params, balls, layout.request, options);
    ++statuses[pot::PotStatusName(plan.status)];
    lifts += plan.reason.find("would hop the ball") != std::string::npos;
    if (plan.status != pot::PotStatus::kOk) continue;
    ++ok;
    std::string what;
    const double gap = SampledGap(table, radius, balls, plan.stroke, *options.robot, &what);
    EXPECT_GT(gap, 0.0) << "seed " << seed << ": the cue passes " << -gap * 1e3 << " mm into " << what;
    ASSERT_TRUE(plan.clearance.has_value());
    EXPECT_TRUE(plan.clearance->clears);
    elevations.push_back(plan.stroke.elevation * 180.0 / M_PI);
    elevated += plan.stroke.elevation > 0.0;
  }
  std::cout << "1000 pots, gantry: " << ok << " ok, " << elevated << " elevated; elevation median "
            << Quantile(elevations, 0.5) << " deg, p90 " << Quantile(elevations, 0.9) << " deg, max "
            << Quantile(elevations, 1.0) << " deg; statuses:";
  for (const auto& [status, n] : statuses) std::cout << " " << status << " " << n;
  std::cout << "; " << lifts << " refusals say a route's cue would hop the ball beyond the limit"
            << std::endl;
  EXPECT_GT(ok, 250);  // the check ran on many strokes
  EXPECT_GT(elevated, 50);  // and the hard layouts made the cue rise
}

TEST(CueClearanceAcceptance, NoChosenStrokePassesTheCueThroughABallTheClothOrARail) {
  constexpr int kChoices = 24;
  const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const physics::ModelParameters params = params::LoadParameters("pool");
  const double radius = params.ball.radius;
  choice::ChoiceOptions options;
  options.samples = 8;
  options.screen_samples = 8;
  options.confirm_samples = 0;
  options.lookahead = false;
  options.pot.robot = params::LoadRobot("gantry");
  batch::ThreadPool pool(2);
  int strokes = 0;
  std::map<std::string, int> statuses;
  // 24 choices (the planned pots above are the thousand). The 20th layout (seed 4719) once hung:
  // its speed window's search halved a bracket one ulp wide without end (pot::Edge, now stopped
  // at adjacent doubles; margin_test's ABracketOfAdjacentDoublesEnds).
  for (int i = 0; i < kChoices; ++i) {
    const std::uint64_t seed = 4700 + static_cast<std::uint64_t>(i);
    const std::vector<table::SceneBall> balls =
        HardLayout(table, radius, seed, i, pot::testing::SeededPotLayout(table, radius, seed).balls);
    const choice::ChoiceResult r = choice::ChooseShot(table, params, balls, options, pool);
    ++statuses[choice::ChoiceStatusName(r.status)];
    const physics::CueStroke* stroke = r.stroke();
    if (!stroke) continue;
    ++strokes;
    std::string what;
    const double gap = SampledGap(table, radius, balls, *stroke, *options.pot.robot, &what);
    EXPECT_GT(gap, 0.0) << "seed " << seed << ": the cue passes " << -gap * 1e3 << " mm into " << what;
  }
  std::cout << kChoices << " choices, gantry: " << strokes << " strokes;";
  for (const auto& [status, n] : statuses) std::cout << " " << status << " " << n;
  std::cout << std::endl;
  EXPECT_GE(strokes, kChoices - 1);
}

}  // namespace
}  // namespace billiard
