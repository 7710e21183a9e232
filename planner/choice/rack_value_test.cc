#include "planner/choice/rack_value.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace billiard::choice {
namespace {

using table::AtRest;
using table::SceneBall;

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
  EXPECT_EQ(RackWinChance(0.0, 0, {0.8, 0.5}), 1.0);
  EXPECT_EQ(RackWinChance(0.3, -1, {0.8, 0.5}), 1.0);
}

// With both rates 1 every shot after the first pots: whoever pots next wins the rack, the scale
// safety.h used before, V = q, whatever the balls left.
TEST(RackWinChanceTest, CertainLaterShotsMakeTheFirstShotTheRack) {
  const RunOutRates certain{1.0, 1.0};
  for (int m : {1, 2, 5, 9}) {
    for (double q : {0.0, 0.25, 0.8}) EXPECT_NEAR(RackWinChance(q, m, certain), q, 1e-12);
  }
}

// The last ball: pot it (q) or miss and the other player arrives on it with a, and on their miss
// we arrive with a, ...: W = q + (1 - q)(1 - A), A = a / (1 - (1 - a)^2) = 1 / (2 - a).
TEST(RackWinChanceTest, TheLastBallIsAGeometricSeriesOfVisits) {
  const RunOutRates rates{0.9, 0.6};
  const double arriving = 1.0 / (2.0 - rates.arrival_chance);
  EXPECT_NEAR(RackWinChance(0.3, 1, rates), 0.3 + 0.7 * (1.0 - arriving), 1e-12);
}

// The race played out with random draws: the shooter's chance of winning from m balls with a
// first shot q, the later shots at pot_rate, an arriving player's first at arrival_chance; the
// closed form within 4 standard errors of the played frequency.
TEST(RackWinChanceTest, AgreesWithTheRacePlayedOut) {
  const RunOutRates rates{0.85, 0.55};
  std::mt19937_64 random(2016);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  constexpr int kRaces = 200000;
  for (int m : {1, 3, 9}) {
    for (double q : {0.2, 0.7}) {
      int won = 0;
      for (int race = 0; race < kRaces; ++race) {
        int left = m, shooter = 0;
        double chance = q;
        while (left > 0) {
          if (uniform(random) < chance) {
            --left;
            chance = rates.pot_rate;
          } else {
            shooter = 1 - shooter;
            chance = rates.arrival_chance;
          }
        }
        won += shooter == 0;  // the last pot wins
      }
      const double played = static_cast<double>(won) / kRaces;
      const double w = RackWinChance(q, m, rates);
      EXPECT_NEAR(w, played, 4 * std::sqrt(w * (1 - w) / kRaces)) << "m " << m << " q " << q;
    }
  }
}

// A better first shot is worth more; more balls to pot make the same first shot worth less
// (the later shots may miss) but never less than what missing it gives.
TEST(RackWinChanceTest, RisesWithTheFirstShotAndFallsWithTheBallsLeft) {
  const RunOutRates rates{0.9, 0.6};
  for (int m = 1; m <= 9; ++m) {
    EXPECT_LT(RackWinChance(0.2, m, rates), RackWinChance(0.6, m, rates));
    if (m > 1) {
      EXPECT_LT(RackWinChance(0.8, m, rates), RackWinChance(0.8, m - 1, rates));
    }
  }
}

}  // namespace
}  // namespace billiard::choice
