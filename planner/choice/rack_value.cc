#include "planner/choice/rack_value.h"

#include <algorithm>

#include "sim/rules/eight_ball.h"
#include "sim/rules/ruleset.h"

namespace billiard::choice {

namespace {

// The least arrival chance the two-count race is solved at (RackWinChance).
constexpr double kLeastArrivalChance = 1e-9;

int Count(const std::vector<table::SceneBall>& balls, rules::Group group) {
  return static_cast<int>(std::count_if(balls.begin(), balls.end(), [&](const table::SceneBall& b) {
    return b.id != 0 && rules::GroupOf(b.id) == group;
  }));
}

// Nine-ball's race of one count m: W_m(q), the recursion climbed from W_0 = 1.
double SharedRace(double first_shot, int m, const RunOutRates& rates) {
  const double p = rates.pot_rate;
  const double a = rates.arrival_chance;
  double continuing = 1.0;  // W_{k-1}(pot_rate)
  double arriving = 1.0;    // A_k = (a W_{k-1}(pot_rate) + 1 - a) / (2 - a)
  for (int k = 1; k <= m; ++k) {
    arriving = (a * continuing + 1.0 - a) / (2.0 - a);
    if (k < m) continuing = p * continuing + (1.0 - p) * (1.0 - arriving);
  }
  return first_shot * continuing + (1.0 - first_shot) * (1.0 - arriving);
}

// Eight-ball's race of two counts: V(i, j) and U(i, j) for i, j <= max(m, n), in order of i + j
// (each pair needs V of pairs one ball shorter), then W(q; m, n).
double SeparateRaces(double first_shot, int m, int n, const RunOutRates& rates) {
  const int size = std::max(m, n) + 1;
  const double p = rates.pot_rate;
  const double a = rates.arrival_chance;
  const double r = 1.0 - a;  // an arriving shot's miss
  // Index (i, j): the shooter i balls, the other j. A player with nothing left has won.
  std::vector<double> v(size * size, 1.0), u(size * size, 1.0);
  auto at = [size](int i, int j) { return i * size + j; };
  for (int sum = 2; sum <= 2 * (size - 1); ++sum) {
    for (int i = std::max(1, sum - (size - 1)); i <= std::min(size - 1, sum - 1); ++i) {
      const int j = sum - i;
      if (j < i) continue;  // (i, j) and (j, i) solve together
      // U(i, j) = a V(i-1, j) + r (1 - U(j, i)), and the same with i and j swapped.
      const double ci = a * v[at(i - 1, j)] + r;
      const double cj = a * v[at(j - 1, i)] + r;
      u[at(i, j)] = (ci - r * cj) / (1.0 - r * r);
      u[at(j, i)] = (cj - r * ci) / (1.0 - r * r);
      v[at(i, j)] = p * v[at(i - 1, j)] + (1.0 - p) * (1.0 - u[at(j, i)]);
      v[at(j, i)] = p * v[at(j - 1, i)] + (1.0 - p) * (1.0 - u[at(i, j)]);
    }
  }
  return first_shot * v[at(m - 1, n)] + (1.0 - first_shot) * (1.0 - u[at(n, m)]);
}

}  // namespace

int RunLength(const std::vector<table::SceneBall>& balls, rules::Rules rules) {
  if (rules::RulesetOf(rules).RackOver(balls)) return 0;
  const int eight = 1;  // under eight-ball the 8 is potted last
  switch (rules) {
    case rules::Rules::kEightBallSolids:
      return Count(balls, rules::Group::kSolids) + eight;
    case rules::Rules::kEightBallStripes:
      return Count(balls, rules::Group::kStripes) + eight;
    case rules::Rules::kEightBall:
      return std::min(Count(balls, rules::Group::kSolids), Count(balls, rules::Group::kStripes)) +
             eight;
    default:
      return static_cast<int>(std::count_if(balls.begin(), balls.end(),
                                            [](const table::SceneBall& b) { return b.id != 0; }));
  }
}

RunOutRates MeasuredRunOutRates(rules::Rules rules) {
  if (rules::IsEightBall(rules)) return {733.0 / 925.0, 172.0 / 264.0};
  return {272.0 / 331.0, 74.0 / 168.0};
}

Race RaceOf(const std::vector<table::SceneBall>& balls, rules::Rules shooter, rules::Rules other) {
  return {RunLength(balls, shooter), RunLength(balls, other), !rules::IsEightBall(shooter)};
}

double RackWinChance(double first_shot, const Race& race, const RunOutRates& rates) {
  if (race.shooter <= 0) return 1.0;
  if (race.shared) return SharedRace(first_shot, race.shooter, rates);
  // The other player with nothing left has won: their rack is over before our shot.
  if (race.other <= 0) return 0.0;
  // Players that never pot on arriving leave the two races' split undetermined (1 - r^2 = 0):
  // taken as the limit of ever so rare pots.
  RunOutRates bounded = rates;
  bounded.arrival_chance = std::max(rates.arrival_chance, kLeastArrivalChance);
  return SeparateRaces(first_shot, race.shooter, race.other, bounded);
}

}  // namespace billiard::choice
