// What a choice is told: the rules it plays under, the noise it assumes, how many executions
// each of its steps runs (shot_choice.h), and the pots it considers.
//
// Module: billiard::choice.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "planner/pot/pot_planner.h"
#include "sim/params/execution_noise.h"
#include "sim/rules/rules.h"

namespace billiard::choice {

// The games a choice plays under (sim/rules/rules.h): their legal targets are its candidates'
// balls, and their end of the rack its lookahead's.
using rules::Rules;

struct ChoiceOptions {
  Rules rules = Rules::kAny;
  params::ExecutionNoise noise = params::LoadNoise(params::kDefaultNoise);
  int samples = 64;         // full-model executions of each finalist
  int screen_samples = 16;  // closed-form executions of each candidate
  int finalists = 4;        // candidates that reach the full model
  // Fresh full-model executions of the chosen shot alone, on their own seed stream: the
  // probability reported (a binomial standard error of at most 0.5 / sqrt(n), 0.03 at 256).
  // 0: report the finalists' own (biased) estimate.
  int confirm_samples = 256;
  // Sequential Monte Carlo (race.h): the finalists raced in rounds of race_round executions,
  // one stopping when its score's upper bound (race_z standard errors) is below the leader's
  // lower bound; the confirmation in rounds of confirm_round, stopping once the standard error
  // of its probability is confirm_stderr or less (at most confirm_samples).
  int race_round = 16;
  double race_z = 2.58;  // two-sided 99 % for each comparison
  int confirm_round = 32;
  double confirm_stderr = 0.03;
  std::uint64_t seed = 1;
  // Each execution on the table's constants drawn within the parameter set's uncertainty, when
  // it has one (monte_carlo.h); false: on the set's own values, the constants taken as exact.
  bool sample_constants = true;
  bool lookahead = true;  // score p (1 + v); false: p alone
  // Below this probability the choice says that no shot is likely.
  double likely = 0.5;
  // With the lookahead, the best screened candidates planned again with position play: the cue
  // ball sent within position_radius of the place the next shot looks easiest from.
  int position_plans = 3;
  double position_radius = 0.15;  // [m]
  // The lookahead's second level (second_level.h): the next shot planned (PlanPot, screened) on
  // the clusters of each finalist's outcomes, and position play's target chosen among the first
  // position_places places by it; false: the next shot valued in closed form (EasyPotEstimate).
  bool second_level = true;
  int second_level_states = 3;   // clusters of outcomes valued per finalist
  int next_plans = 2;            // the next shot's plans screened: the widest heading windows
  int next_samples = 16;         // closed-form executions of each next-shot plan screened
  double cluster_radius = 0.1;   // [m] every ball of a cluster's tables within it of another's
  int position_places = 3;
  std::vector<pot::ShotKind> next_kinds = {pot::ShotKind::kDirect};  // the next shot's kinds
  int placements = 3;             // ball in hand: the places chosen among (ball_in_hand.h)
  // Safeties (safety.h), weighed only when the best pot's reported probability is below
  // safety_below (or nothing plans): each candidate screened safety_screen_samples times on
  // the closed form, the best safety_finalists and the attempt safety_samples times on the full
  // model.
  double safety_below = 0.6;
  int safety_screen_samples = 8;
  int safety_finalists = 3;
  int safety_samples = 48;
  std::vector<pot::ShotKind> kinds = {pot::ShotKind::kDirect, pot::ShotKind::kBank,
                                      pot::ShotKind::kKick, pot::ShotKind::kCurve};
  pot::PotOptions pot;
  // The heading margins of the pots it plans (pot::PotOptions::margin_cap, margin_stride): they
  // only rank plans (within PlanPot a kind's widest route, the screening's tie-break, the second
  // level's most forgiving next pots); a plan's chance is the noise's, sampled. So the walk stops
  // at margin_cap_deg, 8 standard deviations of the computational-pool heading noise (0.125
  // degree; 10 of the robot's 0.1), past which a wider window changes no probability, and plays
  // every margin_stride-th heading of the 0.01-degree grid (0.04 degree, a third of either
  // deviation), the edge found by bisection between: most of a choice's time was the walk.
  double margin_cap_deg = 1.0;
  int margin_stride = 4;
  // The chosen pot's margin walked in full once it is chosen (pot::StateMargins), as a choice
  // states it (choose-shot, planner_node); false: as ranked (a rack's players, planner/game/).
  bool state_margin = true;
};

// options.pot with the walk of the margins it ranks plans by (margin_cap_deg, margin_stride).
inline pot::PotOptions RankingPotOptions(const ChoiceOptions& options) {
  pot::PotOptions ranking = options.pot;
  ranking.margin_cap = options.margin_cap_deg * M_PI / 180.0;
  ranking.margin_stride = options.margin_stride;
  return ranking;
}

}  // namespace billiard::choice
