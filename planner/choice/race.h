// Sequential Monte Carlo for steps 3 and 5 of a choice (shot_choice.h): the samples a decision
// needs, not a fixed count.
//
// Step 3 races the finalists (Maron and Moore 1994, "Hoeffding races"): every finalist still
// racing is played `race_round` more times on the full model, and after each round a finalist
// whose score's upper confidence bound lies below the leader's lower bound stops: more samples
// could not make it the choice. The race ends at `samples` executions or when one finalist is
// left. Step 5 confirms the chosen shot in rounds of `confirm_round` until the standard error of
// its probability is `confirm_stderr` or less, or `confirm_samples` are played: a shot that
// pots 95 % of the time is known to 0.03 after 64 executions, one at 70 % after 256.
//
// Both stay deterministic: execution s of a stroke is the same whichever round plays it
// (ExecuteRange: noise from SampleSeed(seed, s)), and the stopping rules read the results in
// index order, so a seed gives the same choice on any thread count.
//
// Module: billiard::choice.
#pragma once

#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/choice/monte_carlo.h"
#include "planner/pot/pot_planner.h"
#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice {

// A score's confidence interval from executions of one stroke.
struct ScoreBounds {
  double mean = 0.0;  // p (1 + v) (p without the lookahead): Score of the executions' tally
  double low = 0.0;
  double high = 0.0;
};

// The mean of X = potted (1 + next value) (X = potted without the lookahead) over `executions`
// and mean -+ z s / sqrt(n), s the sample deviation of X floored at what the Agresti and Coull
// (1998) estimate p~ = (pots + 2) / (n + 4) gives, sqrt(p~ (1 - p~)) (1 + v): a stroke that
// potted every time so far is not yet certain.
ScoreBounds BoundsOf(const std::vector<Execution>& executions, bool lookahead, double z);

// Races `plans` on the full model (`motion`) as above; each plan's executions in sample order
// (a stopped one's fewer). At least one round is played by every plan.
std::vector<std::vector<Execution>> RaceFinalists(const table::TableGeometry& table,
                                                  const physics::ModelParameters& params,
                                                  const std::vector<table::SceneBall>& balls,
                                                  const std::vector<const pot::PotPlan*>& plans,
                                                  const ChoiceOptions& options,
                                                  const Motion& motion, batch::ThreadPool& pool);

// `plan`'s legal pot rate on `motion`, played in rounds until its Agresti-Coull standard error
// sqrt(p~ (1 - p~) / (n + 4)) is options.confirm_stderr or less, or options.confirm_samples are
// played; execution s seeded SampleSeed(options.seed, s).
PotProbability ConfirmToPrecision(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const pot::PotPlan& plan, const ChoiceOptions& options,
                                  const Motion& motion, batch::ThreadPool& pool);

}  // namespace billiard::choice
