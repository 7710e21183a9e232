#include "planner/choice/rack_value.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace billiard::choice {
namespace {

using table::AtRest;
using table::SceneBall;

// Nine-ball's race: m balls, both players potting from them.
Race Shared(int m) { return {m, m, true}; }

std::vector<SceneBall> Balls(const std::vector<int>& ids) {
  std::vector<SceneBall> balls = {AtRest(0, 0.5, 0.5)};
  for (int id : ids) balls.push_back(AtRest(id, 0.1 * id, 0.3));
  return balls;
}

TEST(RunLengthTest, CountsTheBallsLeftToPotUnderEachGame) {
  EXPECT_EQ(RunLength(Balls({3, 5, 9}), rules::Rules::kNineBall), 3);
  EXPECT_EQ(RunLength(Balls({3, 5}), rules::Rules::kNineBall), 0);  // the 9 gone: the rack is over
  const std::vector<SceneBall> eight = Balls({1, 2, 8, 9, 10, 11});
  EXPECT_EQ(RunLength(eight, rules::Rules::kEightBallSolids), 3);   // 1, 2 and the 8
  EXPECT_EQ(RunLength(eight, rules::Rules::kEightBallStripes), 4);  // 9, 10, 11 and the 8
  EXPECT_EQ(RunLength(eight, rules::Rules::kEightBall), 3);         // open: the smaller group
  EXPECT_EQ(RunLength(Balls({8}), rules::Rules::kEightBallSolids), 1);
  EXPECT_EQ(RunLength(Balls({1, 2}), rules::Rules::kEightBallSolids), 0);  // the 8 gone
}

TEST(RackWinChanceTest, NoBallLeftIsARackWon) {
  EXPECT_EQ(RackWinChance(0.0, Shared(0), {0.8, 0.5}), 1.0);
  EXPECT_EQ(RackWinChance(0.3, Shared(-1), {0.8, 0.5}), 1.0);
}

// With both rates 1 every shot after the first pots: whoever pots next wins the rack, the scale
// safety.h used before, V = q, whatever the balls left.
TEST(RackWinChanceTest, CertainLaterShotsMakeTheFirstShotTheRack) {
  const RunOutRates certain{1.0, 1.0};
  for (int m : {1, 2, 5, 9}) {
    for (double q : {0.0, 0.25, 0.8}) EXPECT_NEAR(RackWinChance(q, Shared(m), certain), q, 1e-12);
  }
}

// The last ball: pot it (q) or miss and the other player arrives on it with a, and on their miss
// we arrive with a, ...: W = q + (1 - q)(1 - A), A = a / (1 - (1 - a)^2) = 1 / (2 - a).
TEST(RackWinChanceTest, TheLastBallIsAGeometricSeriesOfVisits) {
  const RunOutRates rates{0.9, 0.6};
  const double arriving = 1.0 / (2.0 - rates.arrival_chance);
  EXPECT_NEAR(RackWinChance(0.3, Shared(1), rates), 0.3 + 0.7 * (1.0 - arriving), 1e-12);
}

// The race played out with random draws: the shooter's chance of winning with a first shot q,
// the later shots at pot_rate, an arriving player's first at arrival_chance, the last pot
// winning; each player's count its own (two counts) or one count both pot from (shared).
double PlayedOut(double q, const Race& race, const RunOutRates& rates, int races) {
  std::mt19937_64 random(2016);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int won = 0;
  for (int r = 0; r < races; ++r) {
    int left[2] = {race.shooter, race.shared ? race.shooter : race.other};
    int shooter = 0;
    double chance = q;
    while (left[shooter] > 0) {
      if (uniform(random) < chance) {
        --left[shooter];
        if (race.shared) left[1 - shooter] = left[shooter];
        chance = rates.pot_rate;
      } else {
        shooter = 1 - shooter;
        chance = rates.arrival_chance;
      }
    }
    won += shooter == 0;
  }
  return static_cast<double>(won) / races;
}

// The closed form (shared) and the recursion (two counts) within 4 standard errors of the race
// played out.
TEST(RackWinChanceTest, AgreesWithTheRacePlayedOut) {
  const RunOutRates rates{0.85, 0.55};
  constexpr int kRaces = 200000;
  for (const Race& race : {Shared(1), Shared(3), Shared(9), Race{1, 7, false}, Race{4, 2, false},
                           Race{8, 8, false}}) {
    for (double q : {0.2, 0.7}) {
      const double w = RackWinChance(q, race, rates);
      EXPECT_NEAR(w, PlayedOut(q, race, rates, kRaces), 4 * std::sqrt(w * (1 - w) / kRaces))
          << race.shooter << " against " << race.other << (race.shared ? " shared" : "")
          << ", q " << q;
    }
  }
}

// Under eight-ball the other player's count matters: the further they are from the 8, the more
// a miss of ours is worth; with nothing left the rack is theirs.
TEST(RackWinChanceTest, TwoRacesRiseWithTheOtherPlayersCount) {
  const RunOutRates rates{0.75, 0.6};
  for (int n = 2; n <= 8; ++n) {
    EXPECT_GT(RackWinChance(0.4, {3, n, false}, rates), RackWinChance(0.4, {3, n - 1, false}, rates));
  }
  EXPECT_EQ(RackWinChance(0.9, {3, 0, false}, rates), 0.0);
  EXPECT_EQ(RackWinChance(0.0, {0, 3, false}, rates), 1.0);
}

TEST(RaceOfTest, NineBallSharesItsBallsAndEightBallRacesByGroup) {
  const std::vector<SceneBall> nine = Balls({3, 5, 9});
  const Race shared = RaceOf(nine, rules::Rules::kNineBall, rules::Rules::kNineBall);
  EXPECT_EQ(shared.shooter, 3);
  EXPECT_EQ(shared.other, 3);
  EXPECT_TRUE(shared.shared);
  const Race groups = RaceOf(Balls({1, 2, 8, 9, 10, 11}), rules::Rules::kEightBallSolids,
                             rules::Rules::kEightBallStripes);
  EXPECT_EQ(groups.shooter, 3);
  EXPECT_EQ(groups.other, 4);
  EXPECT_FALSE(groups.shared);
}

// A better first shot is worth more; more balls to pot make the same first shot worth less
// (the later shots may miss) but never less than what missing it gives.
TEST(RackWinChanceTest, RisesWithTheFirstShotAndFallsWithTheBallsLeft) {
  const RunOutRates rates{0.9, 0.6};
  for (int m = 1; m <= 9; ++m) {
    EXPECT_LT(RackWinChance(0.2, Shared(m), rates), RackWinChance(0.6, Shared(m), rates));
    if (m > 1) {
      EXPECT_LT(RackWinChance(0.8, Shared(m), rates), RackWinChance(0.8, Shared(m - 1), rates));
    }
  }
}

}  // namespace
}  // namespace billiard::choice
