#include "sim/table/rack.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "sim/params/table_specs.h"

namespace billiard::table {
namespace {

using Eigen::Vector2d;

// Ball radii of the games' rules: WPA 2.25 in, WPBSA 52.5 mm, UMB 61.5 mm.
constexpr double kPoolRadius = 0.5 * 2.25 * 0.0254;
constexpr double kSnookerRadius = 0.5 * 0.0525;
constexpr double kCaromRadius = 0.5 * 0.0615;
constexpr int kSeeds = 100;

struct RackCase {
  RackKind kind;
  const char* table;
  double radius;
  std::size_t balls;
};

const RackCase kCases[] = {{RackKind::kEightBall, "pool-9ft", kPoolRadius, 16},
                           {RackKind::kNineBall, "pool-7ft", kPoolRadius, 10},
                           {RackKind::kSnooker, "snooker-12ft", kSnookerRadius, 22},
                           {RackKind::kThreeCushion, "carom-10ft", kCaromRadius, 3}};

TableGeometry Built(const std::string& name) { return BuildTable(params::LoadTableSpec(name)); }

Vector2d At(const SceneBall& ball) { return ball.state.head<2>(); }

std::map<int, Vector2d> ById(const std::vector<SceneBall>& balls) {
  std::map<int, Vector2d> places;
  for (const SceneBall& ball : balls) places[ball.id] = At(ball);
  return places;
}

// Every rack: the right number of distinct ids from 0, the cue ball first, every ball at rest on
// the surface, no two overlapping, and balls that touch in a real rack 0 to 0.1 mm apart.
TEST(RackTest, BallsOnTheSurfaceApartByATinyGap) {
  for (const RackCase& c : kCases) {
    SCOPED_TRACE(c.table);
    const TableGeometry table = Built(c.table);
    for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
      const std::vector<SceneBall> balls = Rack(c.kind, table, c.radius, seed);
      ASSERT_EQ(balls.size(), c.balls);
      EXPECT_EQ(balls.front().id, 0);
      std::set<int> ids;
      for (const SceneBall& ball : balls) {
        ids.insert(ball.id);
        EXPECT_TRUE(table.OnSurface(At(ball), c.radius)) << "ball " << ball.id;
        EXPECT_EQ(ball.state.tail<5>().norm(), 0.0) << "ball " << ball.id << " not at rest";
      }
      EXPECT_EQ(ids.size(), c.balls);
      EXPECT_EQ(*ids.rbegin(), static_cast<int>(c.balls) - 1);
      for (std::size_t i = 0; i < balls.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
          const double gap = (At(balls[i]) - At(balls[j])).norm() - 2 * c.radius;
          EXPECT_GE(gap, 0) << "balls " << balls[i].id << " and " << balls[j].id << " overlap";
          if (gap < 1e-3) {
            EXPECT_LE(gap, kRackGap) << balls[i].id << ", " << balls[j].id;
          }
        }
      }
    }
  }
}

// WPA / BCA eight-ball: the apex ball on the foot spot (the middle of the foot half), the 8 in
// the middle of the third row (two rows of sqrt(3) R behind the apex), a solid and a stripe in
// the back corners (four rows behind, 4 R either side of the long axis).
TEST(RackTest, EightBallAsTheRulesPlaceIt) {
  const TableGeometry table = Built("pool-9ft");
  const double R = kPoolRadius;
  const Vector2d foot_spot(0.75 * table.length, 0.5 * table.width);
  const double row = std::sqrt(3.0) * R;
  constexpr double kTolerance = 0.5e-3;  // the rack's gaps, summed over four rows
  std::set<std::vector<int>> orders;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const std::vector<SceneBall> balls = Rack(RackKind::kEightBall, table, R, seed);
    const auto places = ById(balls);
    int apex = 0, left = 0, right = 0;
    for (const auto& [id, p] : places) {
      if (id == 0) continue;
      if ((p - foot_spot).norm() < kTolerance) apex = id;
      if ((p - (foot_spot + Vector2d(4 * row, -4 * R))).norm() < kTolerance) left = id;
      if ((p - (foot_spot + Vector2d(4 * row, 4 * R))).norm() < kTolerance) right = id;
    }
    EXPECT_NE(apex, 0) << "no ball on the foot spot";
    EXPECT_LT((places.at(8) - (foot_spot + Vector2d(2 * row, 0))).norm(), kTolerance);
    ASSERT_NE(left, 0);
    ASSERT_NE(right, 0);
    EXPECT_NE(left < 8, right < 8) << "back corners " << left << " and " << right;
    std::vector<int> order;
    for (const SceneBall& ball : balls) order.push_back(ball.id);
    orders.insert(order);
  }
  EXPECT_GT(orders.size(), kSeeds / 2u) << "the seed must shuffle the free balls";
}

// WPA nine-ball: a diamond with the 1 on the foot spot, the 9 in its middle.
TEST(RackTest, NineBallDiamond) {
  const TableGeometry table = Built("pool-9ft");
  const double R = kPoolRadius;
  const Vector2d foot_spot(0.75 * table.length, 0.5 * table.width);
  const double row = std::sqrt(3.0) * R;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const auto places = ById(Rack(RackKind::kNineBall, table, R, seed));
    EXPECT_LT((places.at(1) - foot_spot).norm(), 0.1e-3);
    EXPECT_LT((places.at(9) - (foot_spot + Vector2d(2 * row, 0))).norm(), 0.3e-3);
    double deepest = 0;
    for (const auto& [id, p] : places) {
      if (id != 0) deepest = std::max(deepest, p.x() - foot_spot.x());
    }
    EXPECT_NEAR(deepest, 4 * row, 0.5e-3) << "a diamond is five rows deep";
  }
}

// WPBSA Official Rules of Snooker, section 1 (d)-(f): baulk line 29 in (737 mm) from the bottom
// cushion, D of radius 11.5 in (292 mm) centred on its middle, the brown there, the yellow at
// the D's corner on the right seen from baulk, the green on the left; blue at the centre, pink
// midway between the centre and the top cushion, black 12.75 in (324 mm) from the top cushion.
// The reds behind the pink, the apex one nearly touching it; the cue ball in the D.
TEST(RackTest, SnookerColoursOnTheirSpots) {
  const TableGeometry table = Built("snooker-12ft");
  const double L = table.length, middle = 0.5 * table.width;
  const std::map<int, Vector2d> spots = {
      {kSnookerYellow, {0.737, middle - 0.292}}, {kSnookerGreen, {0.737, middle + 0.292}},
      {kSnookerBrown, {0.737, middle}},          {kSnookerBlue, {0.5 * L, middle}},
      {kSnookerPink, {0.75 * L, middle}},        {kSnookerBlack, {L - 0.324, middle}}};
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const auto places = ById(Rack(RackKind::kSnooker, table, kSnookerRadius, seed));
    for (const auto& [id, spot] : spots) EXPECT_EQ(places.at(id), spot) << "colour " << id;
    const Vector2d pink = spots.at(kSnookerPink);
    double nearest = 1;
    for (int red = 1; red <= 15; ++red) {
      EXPECT_GT(places.at(red).x(), pink.x()) << "red " << red;
      nearest = std::min(nearest, (places.at(red) - pink).norm() - 2 * kSnookerRadius);
    }
    EXPECT_GT(nearest, 0);
    EXPECT_LE(nearest, kRackGap);
    const Vector2d cue = places.at(0);
    EXPECT_LE(cue.x(), 0.737);
    EXPECT_LE((cue - spots.at(kSnookerBrown)).norm(), 0.292) << "cue ball outside the D";
  }
}

// UMB three-cushion: red on the top spot, yellow on the bottom spot (a quarter of the length from
// each end, on the long axis), the white cue ball on a starting spot 182 mm beside the yellow.
TEST(RackTest, ThreeCushionBreakPosition) {
  const TableGeometry table = Built("carom-10ft");
  const double L = table.length, middle = 0.5 * table.width;
  for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
    const auto places = ById(Rack(RackKind::kThreeCushion, table, kCaromRadius, seed));
    EXPECT_EQ(places.at(2), Vector2d(0.75 * L, middle));
    EXPECT_EQ(places.at(1), Vector2d(0.25 * L, middle));
    EXPECT_LE((places.at(0) - Vector2d(0.25 * L, middle - 0.182)).norm(), kCueJitter);
  }
}

TEST(RackTest, SameSeedSameRackOtherSeedOtherRack) {
  for (const RackCase& c : kCases) {
    SCOPED_TRACE(c.table);
    const TableGeometry table = Built(c.table);
    const std::vector<SceneBall> a = Rack(c.kind, table, c.radius, 7);
    const std::vector<SceneBall> b = Rack(c.kind, table, c.radius, 7);
    const std::vector<SceneBall> other = Rack(c.kind, table, c.radius, 8);
    ASSERT_EQ(a.size(), b.size());
    bool differs = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].id, b[i].id);
      EXPECT_EQ(a[i].state, b[i].state);
      differs = differs || a[i].id != other[i].id || a[i].state != other[i].state;
    }
    EXPECT_TRUE(differs);
  }
}

TEST(RackTest, RefusesARackThatDoesNotFit) {
  const TableGeometry table = Built("pool-7ft");
  EXPECT_THROW(Rack(RackKind::kEightBall, table, 0.2, 1), std::invalid_argument);
  EXPECT_THROW(Rack(RackKind::kEightBall, table, -0.02, 1), std::invalid_argument);
}

TEST(RackTest, ParsesTheRackNames) {
  EXPECT_EQ(ParseRackKind("eight-ball"), RackKind::kEightBall);
  EXPECT_EQ(ParseRackKind("nine-ball"), RackKind::kNineBall);
  EXPECT_EQ(ParseRackKind("snooker"), RackKind::kSnooker);
  EXPECT_EQ(ParseRackKind("three-cushion"), RackKind::kThreeCushion);
  EXPECT_THROW(ParseRackKind("eight_ball"), std::invalid_argument);
  EXPECT_THROW(ParseRackKind(""), std::invalid_argument);
}

}  // namespace
}  // namespace billiard::table
