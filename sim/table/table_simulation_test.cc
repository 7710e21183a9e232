// The whole table, event by event: collision times against their closed forms, the failure
// cases other simulators' users reported (pooltool issues: balls passing through each other, a
// corner escape, Newton's cradle, frozen balls, a narrow gap), and 1,000 seeded breaks that must
// keep every ball apart, on the table and losing energy.
#include "sim/table/table_simulation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/table/testing/breaks.h"
#include "sim/table/testing/degenerate_scenes.h"

namespace billiard::table {
namespace {

using physics::BallState;
using physics::kVx;
using physics::kVy;
using physics::kX;
using physics::kY;
using physics::MakeBallState;

physics::ModelParameters Pool() { return params::LoadParameters("pool"); }
TableGeometry Table(const std::string& name) { return BuildTable(params::LoadTableSpec(name)); }

// Elastic balls without friction between them: the textbook limits.
physics::ModelParameters Ideal() {
  physics::ModelParameters p = Pool();
  p.collision.ball_restitution = 1.0;
  p.collision.ball_friction_a = p.collision.ball_friction_b = 0.0;
  return p;
}

std::vector<TableEvent> OfType(const TableSimulation& sim, EventType type) {
  std::vector<TableEvent> out;
  for (const TableEvent& e : sim.events()) {
    if (e.type == type) out.push_back(e);
  }
  return out;
}

// Whether ball i has dropped into a pocket by time t.
bool Dropped(const TableSimulation& sim, std::size_t i, double t) {
  return sim.pocket(i) && t >= sim.segments(i).back().start_time();
}

// The smallest centre distance minus 2 r over all pairs of balls on the table at time t.
double SmallestGap(const TableSimulation& sim, double t, double r) {
  std::vector<Eigen::Vector2d> at;
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    if (!Dropped(sim, i, t)) at.push_back(sim.StateAt(i, t).head<2>());
  }
  double smallest = INFINITY;
  for (std::size_t i = 0; i < at.size(); ++i) {
    for (std::size_t j = i + 1; j < at.size(); ++j) {
      smallest = std::min(smallest, (at[i] - at[j]).norm() - 2.0 * r);
    }
  }
  return smallest;
}

// A ball's first contact is settled by its meeting a ball (as either party) or its drop; its
// cushions, jaws and transitions, and the events of other balls, settle nothing.
TEST(TableSimulation, AFirstContactIsSettledByABallMetOrADrop) {
  const auto event = [](EventType type, int ball, int other) {
    TableEvent e;
    e.type = type;
    e.ball = ball;
    e.other = other;
    return e;
  };
  EXPECT_TRUE(SettlesFirstBallMet(event(EventType::kBallBall, 0, 3), 0));
  EXPECT_TRUE(SettlesFirstBallMet(event(EventType::kBallBall, 3, 0), 0));
  EXPECT_TRUE(SettlesFirstBallMet(event(EventType::kBallPocket, 0, -1), 0));
  EXPECT_FALSE(SettlesFirstBallMet(event(EventType::kBallBall, 2, 3), 0));
  EXPECT_FALSE(SettlesFirstBallMet(event(EventType::kBallPocket, 3, -1), 0));
  for (EventType type : {EventType::kTransition, EventType::kBallCushion, EventType::kBallJaw,
                         EventType::kBallPush}) {
    EXPECT_FALSE(SettlesFirstBallMet(event(type, 0, -1), 0)) << EventTypeName(type);
  }
}

TEST(TableSimulation, HeadOnStunMeetsAtTheSlidingBallsTimeAndSendsHalfOnePlusE) {
  const auto p = Pool();
  const TableGeometry table = Table("pool-9ft");
  const double r = p.ball.radius, v0 = 2.0, gap = 0.01, g = p.ball.gravity, mu = p.contact.mu;
  const double y = table.width / 2;
  TableSimulation sim(table, p,
                      {{0, MakeBallState(0.6, y, v0, 0, 0, 0, 0)},
                       {1, MakeBallState(0.6 + 2 * r + gap, y, 0, 0, 0, 0, 0)}});
  sim.Run(0.05);
  const auto hits = OfType(sim, EventType::kBallBall);
  ASSERT_EQ(hits.size(), 1u);
  // gap = v0 t - mu g t^2 / 2 while the cue ball slides without spin.
  const double t = (v0 - std::sqrt(v0 * v0 - 2 * mu * g * gap)) / (mu * g);
  EXPECT_NEAR(hits[0].time, t, 1e-12);
  const double e = p.collision.ball_restitution;
  EXPECT_NEAR(sim.StateAt(1, hits[0].time)[kVx], (1 + e) / 2 * (v0 - mu * g * t), 1e-12);
}

TEST(TableSimulation, NewtonsCradleSendsTheLastBallAlone) {
  // A cue ball without spin (a stun) touching a row of four frozen balls, elastic and
  // frictionless: the impact runs down the row at one instant, in order, and only the last ball
  // leaves, at the cue ball's speed.
  const auto p = Ideal();
  const TableGeometry table = Table("pool-9ft");
  const double r = p.ball.radius, y = table.width / 2, v = 1.0;
  std::vector<SceneBall> balls{{0, MakeBallState(0.5, y, v, 0, 0, 0, 0)}};
  for (int k = 1; k <= 4; ++k) {
    balls.push_back({k, MakeBallState(0.5 + 2 * r * k, y, 0, 0, 0, 0, 0)});
  }
  TableSimulation sim(table, p, balls);
  sim.Run(0.3);
  const auto hits = OfType(sim, EventType::kBallBall);
  ASSERT_EQ(hits.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(hits[k].time, hits[0].time);
    EXPECT_EQ(hits[k].ball, k);
    EXPECT_EQ(hits[k].other, k + 1);
  }
  EXPECT_EQ(hits[0].time, 0.0);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(sim.StateAt(k, 0.0).segment<2>(kVx).norm(), 0.0);
  EXPECT_NEAR(sim.StateAt(4, 0.0)[kVx], v, 1e-15);
  for (double s = 0.0; s <= 0.3; s += 1e-3) EXPECT_GT(SmallestGap(sim, s, r), -1e-9) << s;
}

TEST(TableSimulation, ARollingCueBallFollowsThroughARowWithoutPassingIt) {
  // With top spin the cue ball, stopped by the impact, is driven on by the cloth into the row it
  // touches: a push, held as a contact. The last ball still takes nearly all the speed, and no
  // ball passes through another.
  const auto p = Pool();
  const TableGeometry table = Table("pool-9ft");
  const double r = p.ball.radius, y = table.width / 2, v = 1.0;
  std::vector<SceneBall> balls{{0, MakeBallState(0.5, y, v, 0, 0, v / r, 0)}};
  for (int k = 1; k <= 4; ++k) {
    balls.push_back({k, MakeBallState(0.6 + 2 * r * k, y, 0, 0, 0, 0, 0)});
  }
  TableSimulation sim(table, p, balls);
  sim.Run();
  EXPECT_TRUE(sim.AtRest());
  const auto hits = OfType(sim, EventType::kBallBall);
  ASSERT_GE(hits.size(), 4u);
  const double t = hits[0].time;
  EXPECT_GT(sim.StateAt(4, t + 1e-3)[kVx], 0.8 * v);
  EXPECT_GT(sim.State(4)[kX], sim.State(3)[kX]);
  for (double s = 0.0; s <= sim.time(); s += 1e-3) EXPECT_GT(SmallestGap(sim, s, r), -1e-9) << s;
  // Balls on one line stay on it.
  for (std::size_t i = 0; i < sim.ball_count(); ++i) EXPECT_NEAR(sim.State(i)[kY], y, 1e-12);
}

TEST(TableSimulation, FrozenBallsPartWithoutOverlapAndKeepTheMomentum) {
  const auto p = Pool();
  const TableGeometry table = Table("pool-9ft");
  const double r = p.ball.radius, y = table.width / 2;
  // Two object balls frozen together across the cue ball's line, the cue ball driven between.
  TableSimulation sim(table, p,
                      {{0, MakeBallState(0.8, y, 3.0, 0, 0, 0, 0)},
                       {1, MakeBallState(1.2, y + r, 0, 0, 0, 0, 0)},
                       {2, MakeBallState(1.2, y - r, 0, 0, 0, 0, 0)}});
  sim.Run();
  EXPECT_TRUE(sim.AtRest());
  for (double s = 0.0; s <= sim.time(); s += 1e-3) EXPECT_GT(SmallestGap(sim, s, r), -1e-9) << s;
  // By symmetry the two object balls leave mirrored about the cue ball's line, and the first
  // contact (exactly simultaneous) is resolved in a fixed order.
  const auto hits = OfType(sim, EventType::kBallBall);
  ASSERT_GE(hits.size(), 2u);
  EXPECT_EQ(hits[0].ball, 0);
  EXPECT_EQ(hits[0].other, 1);
}

TEST(TableSimulation, AFastBallThreadsAGapOneMillimetreWiderThanItself) {
  const auto p = Pool();
  const TableGeometry table = Table("pool-9ft");
  const double r = p.ball.radius, y = table.width / 2;
  for (double extra : {+0.001, -0.001}) {
    // Two balls at rest whose surfaces are 2 r + extra apart, the cue ball at 10 m/s through the
    // middle.
    const double half = r + (2 * r + extra) / 2;
    TableSimulation sim(table, p,
                        {{0, MakeBallState(0.3, y, 10.0, 0, 0, 0, 0)},
                         {1, MakeBallState(1.0, y + half, 0, 0, 0, 0, 0)},
                         {2, MakeBallState(1.0, y - half, 0, 0, 0, 0, 0)}});
    sim.Run(0.2);
    EXPECT_EQ(OfType(sim, EventType::kBallBall).empty(), extra > 0) << extra;
    for (double s = 0.0; s <= 0.2; s += 1e-4) EXPECT_GT(SmallestGap(sim, s, r), -1e-9) << s;
  }
}

TEST(TableSimulation, ACornerShotComesBackOffBothCushions) {
  // A carom table has no pockets: a ball sent into a corner at 45 degrees meets both cushions
  // at the same instant (and, nudged, a few nanoseconds apart). It must come back out.
  const physics::ModelParameters p = params::LoadParameters("carom");
  const TableGeometry table = Table("carom-10ft");
  const double r = p.ball.radius;
  for (double nudge : {0.0, 1e-9, -1e-9}) {
    const double start = 0.5;
    TableSimulation sim(
        table, p,
        {{0, MakeBallState(table.length - start + nudge, table.width - start, 3.0, 3.0, 0, 0, 0)}});
    sim.Run(2.0);
    EXPECT_GE(OfType(sim, EventType::kBallCushion).size(), 2u) << nudge;
    for (double s = 0.0; s <= 2.0; s += 1e-4) {
      const BallState b = sim.StateAt(0, s);
      EXPECT_TRUE(table.OnSurface(b.head<2>(), r * (1 - 1e-9))) << s << " " << b.transpose();
    }
    const double back = OfType(sim, EventType::kBallCushion)[1].time + 1e-3;
    EXPECT_LT(sim.StateAt(0, back)[kVx], 0.0) << nudge;
    EXPECT_LT(sim.StateAt(0, back)[kVy], 0.0) << nudge;
  }
}

TEST(TableSimulation, AStraightPotDropsThroughTheCaptureLine) {
  const auto p = Pool();
  const TableGeometry table = Table("pool-9ft");
  const Pocket* corner = nullptr;
  for (const Pocket& pk : table.pockets) {
    if (pk.name == "upper_right") corner = &pk;
  }
  ASSERT_NE(corner, nullptr);
  const Eigen::Vector2d start(table.length / 2, table.width / 2);
  const Eigen::Vector2d aim = (corner->centre - start).normalized() * 3.0;
  TableSimulation sim(table, p,
                      {{0, MakeBallState(start.x(), start.y(), aim.x(), aim.y(), 0, 0, 0)}});
  sim.Run();
  ASSERT_TRUE(sim.pocket(0));
  EXPECT_EQ(*sim.pocket(0), "upper_right");
  EXPECT_TRUE(sim.AtRest());
}

TEST(TableSimulation, BadScenesAreRefusedNamingTheBall) {
  const auto p = Pool();
  const TableGeometry table = Table("pool-9ft");
  const double r = p.ball.radius;
  const auto refusal = [&](const std::vector<SceneBall>& balls) -> std::string {
    try {
      TableSimulation sim(table, p, balls);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  const BallState here = MakeBallState(1.0, 0.6, 0, 0, 0, 0, 0);
  EXPECT_EQ(refusal({{0, here}}), "");
  EXPECT_NE(refusal({{0, here}, {1, here + MakeBallState(r, 0, 0, 0, 0, 0, 0)}}).find("overlap"),
            std::string::npos);
  EXPECT_NE(refusal({{3, MakeBallState(-0.2, 0.6, 0, 0, 0, 0, 0)}}).find("ball 3"),
            std::string::npos);
  EXPECT_NE(refusal({{0, here}, {0, MakeBallState(2, 0.6, 0, 0, 0, 0, 0)}}).find("repeated"),
            std::string::npos);
  EXPECT_NE(refusal({{0, MakeBallState(1, 0.6, NAN, 0, 0, 0, 0)}}).find("not finite"),
            std::string::npos);
  EXPECT_NE(refusal({{-1, here}}).find("ball -1"), std::string::npos);
}

// What every break must keep, sampled every `dt`: no two balls overlapping by more than
// `overlap`, every ball on the table until it drops, the energy never rising (to `rounding`).
// Returns how many balls dropped.
int ExpectBreaksKeepTheirInvariants(int breaks, const TableSimulationOptions& options, double dt,
                                    double overlap, double rounding) {
  const auto p = Pool();
  const TableGeometry table = Table("pool-9ft");
  const double r = p.ball.radius;
  int pocketed = 0;
  for (std::uint64_t seed = 0; seed < static_cast<std::uint64_t>(breaks); ++seed) {
    TableSimulation sim(table, p, testing::SeededBreak(table, p, seed), options);
    sim.Run();
    EXPECT_TRUE(sim.AtRest()) << "seed " << seed;
    double energy = INFINITY;
    for (double t = 0.0; t <= sim.time(); t += dt) {
      EXPECT_GT(SmallestGap(sim, t, r), -overlap) << "seed " << seed << ", t = " << t;
      double e = 0.0;
      for (std::size_t i = 0; i < sim.ball_count(); ++i) {
        const BallState s = sim.StateAt(i, t);
        e += physics::KineticEnergy(s, p.ball.mass, p.ball.radius);
        if (!Dropped(sim, i, t)) {
          EXPECT_TRUE(table.InsideBoundary(s.head<2>(), r - overlap))
              << "seed " << seed << ", ball " << sim.id(i) << ", t = " << t;
        }
      }
      EXPECT_LE(e, energy * (1 + rounding)) << "seed " << seed << ", t = " << t;
      energy = e;
    }
    for (std::size_t i = 0; i < sim.ball_count(); ++i) pocketed += sim.pocket(i) ? 1 : 0;
    if (::testing::Test::HasFailure()) break;  // one break's failures say it all
  }
  return pocketed;
}

TEST(TableSimulation, AThousandSeededBreaksKeepBallsApartOnTheTableAndLoseEnergy) {
  const int pocketed = ExpectBreaksKeepTheirInvariants(1000, {}, 2e-3, 1e-9, 1e-12);
  // A break at 7 m/s pockets a ball or two on average; a table that swallows nothing (or
  // everything) is wrong.
  EXPECT_GT(pocketed, 300);
  EXPECT_LT(pocketed, 6000);
}

// Every ball moving by the approximate 5-DOF model between events, as `--model approx` runs
// them.
TableSimulationOptions FiveDof() { return testing::MotionOptions("approx", Pool()); }

TEST(TableSimulation, AFiveDofBallMovesAsTheOneBallSimulatorAndCurvesWhereTheClosedFormCannot) {
  // A stun shot with side spin down the middle of the table, alone: between events the table
  // runs the very simulation of sim/physics/simulator.h, and the spin bends its path, which the
  // closed form's point contact leaves straight.
  const auto p = Pool();
  const TableGeometry table = Table("pool-9ft");
  const BallState start = MakeBallState(0.5, table.width / 2, 1.2, 0, 0, 0, 40);
  TableSimulation five(table, p, {{0, start}}, FiveDof());
  five.Run(1.5);
  const BallState alone = physics::Simulate(p, start, 1.5).final_state;
  EXPECT_LT((five.State(0).head<2>() - alone.head<2>()).norm(), 1e-6);  // its dense output
  TableSimulation closed(table, p, {{0, start}});
  closed.Run(1.5);
  EXPECT_EQ(closed.State(0)[kY], table.width / 2);
  EXPECT_GT(std::abs(five.State(0)[kY] - table.width / 2), 1e-4);
}

TEST(TableSimulation, AFiveDofBallMeetsAnotherWhereTheyTouch) {
  const auto p = Pool();
  const TableGeometry table = Table("pool-9ft");
  const double r = p.ball.radius, y = table.width / 2;
  TableSimulation sim(table, p,
                      {{0, MakeBallState(0.5, y, 2.0, 0.02, 0, 0, 25)},
                       {1, MakeBallState(1.2, y + 0.02, 0, 0, 0, 0, 0)}},
                      FiveDof());
  sim.Run(1.0);
  const auto hits = OfType(sim, EventType::kBallBall);
  ASSERT_GE(hits.size(), 1u);
  // At the event the centres are 2 r apart (to the contact tolerance), and never nearer before.
  EXPECT_NEAR(SmallestGap(sim, hits[0].time, r), 0.0, 2e-9);
  for (double t = 0.0; t < hits[0].time; t += 1e-4) EXPECT_GT(SmallestGap(sim, t, r), 0.0) << t;
  EXPECT_GT(sim.StateAt(1, hits[0].time + 1e-3)[kVx], 1.0);
}

TEST(TableSimulation, SeededBreaksByTheFiveDofModelKeepBallsApartOnTheTableAndLoseEnergy) {
  // A pushed 5-DOF ball (its spin curving it into a ball it rolls past) may overlap that ball by
  // up to 1.5e-7 m before the push is met (contact_search.h, kPushOverlap).
  ExpectBreaksKeepTheirInvariants(60, FiveDof(), 5e-3, 2e-7, 1e-9);
}

TEST(TableSimulation, AutoGivesTheClosedFormToRollingBallsWithLittleSideSpin) {
  const auto p = Pool();
  const double r = p.ball.radius;
  const physics::SimulationOptions method;
  EXPECT_FALSE(FiveDofWhereNeeded(MakeBallState(1, 0.6, 1, 0, 0, 1 / r, 5), p, method));
  EXPECT_TRUE(FiveDofWhereNeeded(MakeBallState(1, 0.6, 1, 0, 0, 0, 0), p, method));  // sliding
  EXPECT_TRUE(FiveDofWhereNeeded(MakeBallState(1, 0.6, 1, 0, 0, 1 / r, 40), p, method));
  // Why 20 rad/s: rolling 7 m with that much side spin the 5-DOF path bends by under a mm.
  const BallState rolling = MakeBallState(0, 0, 1, 0, 0, 1 / r, 20);
  const BallState five = physics::Simulate(p, rolling, 20.0).final_state;
  const BallState closed =
      physics::Simulate(p, rolling, 20.0, {physics::Model::kClosedForm}).final_state;
  EXPECT_LT((five.head<2>() - closed.head<2>()).norm(), 1e-3);
  EXPECT_GT(five[kX], 7.0);
}

}  // namespace
}  // namespace billiard::table
