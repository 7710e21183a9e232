// The candidates of a choice (step 1, shot_choice.h): every legal object ball (all of them, or
// under nine-ball rules the lowest-numbered) x every pocket x every kind (direct, bank, kick,
// curve) that plans, and what the later steps learn of each.
//
// Module: billiard::choice.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/choice/monte_carlo.h"
#include "planner/pot/pot_planner.h"
#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice {

struct Candidate {
  pot::PotPlan plan;
  std::optional<Eigen::Vector2d> position_target;  // position play: where the cue ball is sent
  double screen_probability = 0.0;
  bool finalist = false;
  PotProbability full;           // finalists only: the estimate that chose among them
  // The chosen alone (ChoiceOptions::confirm_samples > 0): the estimate from fresh executions,
  // independent of the choice, and the one reported.
  PotProbability confirmed;
  double next_shot_value = 0.0;  // mean over the potting executions; finalists only
  double score = 0.0;  // p (1 + v), or p without the lookahead: the full model's for finalists

  // The probability to report: the confirmed one when there is one, else the finalists'.
  const PotProbability& reported() const { return confirmed.samples > 0 ? confirmed : full; }
};

// The plans of every legal target (under options.rules), pocket and kind (options.kinds), in
// that order, planned by pot::PlanPot on `pool`'s threads; a plan refused (blocked, too thin, a
// scratch it cannot avoid) is no candidate.
std::vector<pot::PotPlan> PlanCandidates(const table::TableGeometry& table,
                                         const physics::ModelParameters& params,
                                         const std::vector<table::SceneBall>& balls,
                                         const ChoiceOptions& options, batch::ThreadPool& pool);

// The plans of candidates `which` of `candidates`, in that order (for ExecuteAll; they point
// into `candidates`).
std::vector<const pot::PotPlan*> PlansOf(const std::vector<Candidate>& candidates,
                                         const std::vector<std::size_t>& which);

}  // namespace billiard::choice
