// Shot choice: which pot to play when the robot's arm is not exact.
//
// A pot the planner (planner/pot/) finds is exact for the stroke it returns; the robot plays
// that stroke with an error (sim/params/execution_noise.h). The choice therefore asks of each
// pot how likely it is to drop as played, and how good the table it leaves is:
//  1. candidates: every legal object ball (all of them, or under nine-ball rules the
//     lowest-numbered) x every pocket x every kind (direct, bank, kick, curve) that plans;
//  2. screening: each candidate's probability from a few noisy executions with the closed-form
//     motion (Jaroukh 2019, exact for the level-cue paths most pots are, and cheap), and the
//     best few planned again with position play (the cue ball sent to where the next shot looks
//     easiest) and screened too;
//  3. the finalists (the few best screened) raced with noisy executions on the full model the
//     table runs (model_choice::TableMotion; race.h: a finalist stops once more samples could
//     not make it the choice): the probability of a legal pot (the object ball
//     in the called pocket, the cue ball's first contact that ball, no scratch) and its
//     standard error, and, over the executions that pot, the value of the best next shot on the
//     table each leaves (EasyPotEstimate, a closed-form estimate: no planning inside a sample);
//  4. the score: the expected number of balls over this shot and the next, p (1 + v), or p alone
//     without the lookahead. The best scored is the choice;
//  5. the chosen shot's probability estimated again from fresh executions (a seed stream of its
//     own, until its standard error is ChoiceOptions::confirm_stderr, at most confirm_samples
//     of them): the finalists' estimates chose it, so the
//     best of them is biased up (the maximum of noisy estimates: a winner's curse), and the
//     reported probability must not come from the samples that selected. When that probability
//     is below ChoiceOptions::likely the choice says that no shot is likely and still plays it.
// This is the scheme of the computational-pool programs that won their tournaments (Smith
// 2007's PickPocket: Monte Carlo over the noise with a lookahead; Archibald, Altman and Shoham
// 2009's CueCard), here over the robot's own noise and a table model that includes throw,
// squirt and the cushions' impacts.
//
// Each step is a file: candidates.h (1), screening.h and position_play.h (2), monte_carlo.h
// (the executions of 2, 3 and 5), race.h (how many of 3 and 5), lookahead.h (the next shot's value); ball_in_hand.h places
// the cue ball first and easiest_looking.h is the baseline without any of it.
//
// Deterministic: execution s of every candidate draws its noise from a generator seeded by
// (seed, s) alone (common random numbers: candidates are compared on the same errors), each
// execution's result is stored at its index and the sums run in index order, so a seed gives the
// same choice on 1 thread or 64.
//
// Module: billiard::choice. Includes the pot planner, the table, the parameter sets (the noise),
// the rules, the table's motion rule and the thread pool.
#pragma once

#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/choice/choice_result.h"
#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice {

// The choice on `balls` (id 0 the cue ball, every ball at rest).
ChoiceResult ChooseShot(const table::TableGeometry& table, const physics::ModelParameters& params,
                        const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
                        batch::ThreadPool& pool);

// Steps 1-4 of the choice: the chosen's probability is still the finalists'.
ChoiceResult ChooseUnconfirmed(const table::TableGeometry& table,
                               const physics::ModelParameters& params,
                               const std::vector<table::SceneBall>& balls,
                               const ChoiceOptions& options, batch::ThreadPool& pool);

// Step 5: the chosen shot played confirm_samples more times on `balls` with fresh noise, its
// probability the one reported and judged likely or not. Nothing when `result` is not ok.
void Confirm(const table::TableGeometry& table, const physics::ModelParameters& params,
             const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
             batch::ThreadPool& pool, ChoiceResult* result);

}  // namespace billiard::choice
