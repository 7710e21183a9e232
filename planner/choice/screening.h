// Screening (step 2, shot_choice.h): each candidate's stroke played a few times with the noise
// on the closed-form motion (Jaroukh 2019, exact for the level-cue paths most pots are, and
// cheap), its legal pot rate and, with the lookahead, the mean value of the next shot on the
// tables the pots leave; scored p (1 + v). The best screened go on to the full model.
//
// Module: billiard::choice.
#pragma once

#include <cstddef>
#include <vector>

#include "planner/choice/candidates.h"
#include "planner/choice/choice_options.h"
#include "planner/choice/monte_carlo.h"
#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice {

// The executions of one candidate: its pot rate and the mean next-shot value of the executions
// that pot.
struct Tally {
  PotProbability pots;
  double next_shot_value = 0.0;
};

// The tally of the k-th candidate of a batch of `samples` executions each (ExecuteAll's order).
Tally TallyOf(const std::vector<Execution>& executions, std::size_t k, int samples);

// p (1 + v) with the lookahead, p alone without it.
double Score(const Tally& tally, bool lookahead);

// Screens candidates `which`: screen_samples closed-form executions each, their legal pot rate
// and, with the lookahead, the mean next-shot value of those that pot; score p (1 + v). Returns
// the simulations run.
int Screen(const table::TableGeometry& table, const physics::ModelParameters& params,
           const std::vector<table::SceneBall>& balls, const std::vector<std::size_t>& which,
           const ChoiceOptions& options, batch::ThreadPool& pool, std::vector<Candidate>* candidates);

// The screening's order: the score, ties (often several pots screened at 1) to the wider
// heading window.
bool ScreenedBetter(const Candidate& a, const Candidate& b);

}  // namespace billiard::choice
