#include "planner/choice/rack_value.h"

#include <algorithm>

#include "sim/rules/eight_ball.h"
#include "sim/rules/ruleset.h"

namespace billiard::choice {

namespace {

int Count(const std::vector<table::SceneBall>& balls, rules::Group group) {
  return static_cast<int>(std::count_if(balls.begin(), balls.end(), [&](const table::SceneBall& b) {
    return b.id != 0 && rules::GroupOf(b.id) == group;
  }));
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
  switch (rules) {
    case rules::Rules::kEightBall:
    case rules::Rules::kEightBallSolids:
    case rules::Rules::kEightBallStripes:
      return {368.0 / 486.0, 98.0 / 167.0};
    default:
      return {272.0 / 331.0, 74.0 / 168.0};
  }
}

double RackWinChance(double first_shot, int balls_to_pot, const RunOutRates& rates) {
  if (balls_to_pot <= 0) return 1.0;
  const double p = rates.pot_rate;
  const double a = rates.arrival_chance;
  // W_{m-1}(p) climbed from W_0 = 1; A_m = (a W_{m-1}(p) + 1 - a) / (2 - a).
  double continuing = 1.0;  // W_{m-1}(pot_rate)
  double arriving = 1.0;    // A_m
  for (int m = 1; m <= balls_to_pot; ++m) {
    arriving = (a * continuing + 1.0 - a) / (2.0 - a);
    if (m < balls_to_pot) continuing = p * continuing + (1.0 - p) * (1.0 - arriving);
  }
  return first_shot * continuing + (1.0 - first_shot) * (1.0 - arriving);
}

}  // namespace billiard::choice
