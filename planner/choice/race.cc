#include "planner/choice/race.h"

#include <algorithm>
#include <cmath>

#include "planner/choice/screening.h"

namespace billiard::choice {

namespace {

// The Agresti-Coull (1998) estimate of a proportion: two successes and two failures added.
double AgrestiCoull(int successes, int samples) {
  return (successes + 2.0) / (samples + 4.0);
}

// The plans still racing, in plan order.
std::vector<std::size_t> Racing(const std::vector<bool>& racing) {
  std::vector<std::size_t> live;
  for (std::size_t k = 0; k < racing.size(); ++k) {
    if (racing[k]) live.push_back(k);
  }
  return live;
}

// Stops every racing plan whose upper bound is below the leader's (the best mean, ties to the
// first) lower bound.
void DropTheBeaten(const std::vector<std::vector<Execution>>& runs, const ChoiceOptions& options,
                   std::vector<bool>* racing) {
  const std::vector<std::size_t> live = Racing(*racing);
  std::vector<ScoreBounds> bounds(runs.size());
  std::size_t leader = live.front();
  for (std::size_t k : live) {
    bounds[k] = BoundsOf(runs[k], options.lookahead, options.race_z);
    if (bounds[k].mean > bounds[leader].mean) leader = k;
  }
  for (std::size_t k : live) {
    if (bounds[k].high < bounds[leader].low) (*racing)[k] = false;
  }
}

}  // namespace

ScoreBounds BoundsOf(const std::vector<Execution>& executions, bool lookahead, double z) {
  const int n = static_cast<int>(executions.size());
  if (n == 0) return {};
  const Tally tally = TallyOf(executions, 0, n);
  ScoreBounds b;
  b.mean = Score(tally, lookahead);
  const double worth = lookahead ? 1 + tally.next_shot_value : 1.0;  // a pot's X
  double squares = 0.0;
  for (const Execution& e : executions) {
    const double x = e.potted ? (lookahead ? 1 + e.next_value : 1.0) : 0.0;
    squares += (x - b.mean) * (x - b.mean);
  }
  const double p = AgrestiCoull(tally.pots.successes, n);
  const double floor = std::sqrt(p * (1 - p)) * worth;
  const double deviation = std::max(n > 1 ? std::sqrt(squares / (n - 1)) : 0.0, floor);
  const double half_width = z * deviation / std::sqrt(static_cast<double>(n));
  b.low = b.mean - half_width;
  b.high = b.mean + half_width;
  return b;
}

std::vector<std::vector<Execution>> RaceFinalists(const table::TableGeometry& table,
                                                  const physics::ModelParameters& params,
                                                  const std::vector<table::SceneBall>& balls,
                                                  const std::vector<const pot::PotPlan*>& plans,
                                                  const ChoiceOptions& options,
                                                  const Motion& motion, batch::ThreadPool& pool) {
  std::vector<std::vector<Execution>> runs(plans.size());
  std::vector<bool> racing(plans.size(), true);
  const int round = std::max(1, options.race_round);
  for (int played = 0; played < options.samples && !plans.empty();) {
    const std::vector<std::size_t> live = Racing(racing);
    if (played > 0 && live.size() <= 1) break;
    const int count = std::min(round, options.samples - played);
    std::vector<const pot::PotPlan*> live_plans;
    for (std::size_t k : live) live_plans.push_back(plans[k]);
    const std::vector<Execution> executions = ExecuteRange(
        table, params, balls, live_plans, played, count, options, motion, options.lookahead, pool);
    for (std::size_t j = 0; j < live.size(); ++j) {
      runs[live[j]].insert(runs[live[j]].end(), executions.begin() + j * count,
                           executions.begin() + (j + 1) * count);
    }
    played += count;
    DropTheBeaten(runs, options, &racing);
  }
  return runs;
}

PotProbability ConfirmToPrecision(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const pot::PotPlan& plan, const ChoiceOptions& options,
                                  const Motion& motion, batch::ThreadPool& pool) {
  std::vector<Execution> runs;
  const int round = std::max(1, options.confirm_round);
  while (static_cast<int>(runs.size()) < options.confirm_samples) {
    const int played = static_cast<int>(runs.size());
    const int count = std::min(round, options.confirm_samples - played);
    const std::vector<Execution> executions =
        ExecuteRange(table, params, balls, {&plan}, played, count, options, motion, false, pool);
    runs.insert(runs.end(), executions.begin(), executions.end());
    const PotProbability so_far = PotRateOf(runs);
    const double p = AgrestiCoull(so_far.successes, so_far.samples);
    if (std::sqrt(p * (1 - p) / (so_far.samples + 4)) <= options.confirm_stderr) break;
  }
  return PotRateOf(runs);
}

}  // namespace billiard::choice
