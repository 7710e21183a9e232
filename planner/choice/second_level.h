// The lookahead's second level (step 3, shot_choice.h): the next shot planned on the tables a
// candidate's pots leave, not guessed in closed form.
//
// Why: the closed form (EasyPotEstimate, lookahead.h) sees a straight ghost-ball line and its
// heading tolerance; it calls a next ball that only a bank, a kick or a cut past its limit
// reaches impossible, and one whose straight line is open but whose stroke scratches easy. The
// computational-pool programs searched two levels instead: CueCard (Archibald, Altman and
// Shoham 2009; the agent configuration shipped with FastFiz's client, client/client.conf) runs
// 20-100 noisy samples of each first-level candidate and, on the states they leave, a second
// search of 15-25 samples per shot, clustering similar states so each cluster is searched once.
//
// Here, for each finalist of the first level (its `samples` executions on the full model):
//  1. the executions that pot are clustered by the table they leave (ClusterOutcomes): an
//     execution joins the first cluster whose representative (its first member) holds the same
//     balls, each within options.cluster_radius of where it lies there; else it starts one.
//     The clusters are shared between the finalists, so that a plain pot and its position-play
//     variant leaving the same table are planned once (the cache);
//  2. each finalist's `second_level_states` largest clusters are valued (PlanNextShot): every
//     legal target x pocket x kind of options.next_kinds planned by pot::PlanPot
//     (PlanCandidates), the `next_plans` of widest heading window (the narrower side; the
//     screening's tie-break) each screened `next_samples` times on the closed form (the
//     screening of step 2, its own seed stream), the value the best legal-pot rate; 1 when the
//     rack is over, 0 when nothing plans;
//  3. every potting execution takes the value of its cluster when that was valued, else of the
//     valued cluster of its finalist whose cue ball lies nearest (the cue ball's place is most
//     of what the next shot depends on); the finalist's v is the mean over its potting
//     executions: the estimated chance of continuing after this pot.
// Position play uses the same valuation to choose where to send the cue ball (BestPlaceForNext).
//
// Budget (decision median 1 s, p95 4 s on two cores): the finalists (4) alone, a few clusters
// each (3), direct next pots, the 2 most forgiving screened 16 times (the planning costs more
// than the screening): at most 12 next-shot plannings a choice, and 384 closed-form executions.
// Fewer plans, more samples: the value is the best of noisy rates, biased up the more there are,
// and in steps of 1/next_samples.
//
// Deterministic: the clusters are formed in execution order, the plans and executions of
// PlanCandidates and ExecuteAll are stored by index and the next shot's noise drawn from
// SampleSeed(seed + stream, s): the same values on any thread count.
//
// Module: billiard::choice.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/choice/monte_carlo.h"
#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice {

// A planned value and the table simulations it took.
struct NextShotValue {
  double value = 0.0;
  int simulations = 0;
};

// The next shot from `balls` planned and screened (step 2 above): 1 when the rack is over under
// options.rules, 0 without a cue ball or when nothing plans, else the best screened legal-pot
// rate of the plans screened.
NextShotValue PlanNextShot(const table::TableGeometry& table,
                           const physics::ModelParameters& params,
                           const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
                           batch::ThreadPool& pool);

// The potting executions of `candidates` candidates of `samples` executions each (ExecuteAll's
// order), clustered by the table they left (step 1 above).
struct Outcomes {
  std::vector<std::vector<table::SceneBall>> states;  // each cluster's representative
  // cluster_of[k][s]: the cluster of candidate k's execution s, -1 when it did not pot.
  std::vector<std::vector<int>> cluster_of;
};
Outcomes ClusterOutcomes(const std::vector<Execution>& executions, std::size_t candidates,
                         int samples, double radius);

// Each candidate's next-shot value v by the second level (steps 2 and 3 above), 0 for one that
// never potted, and the simulations run.
struct SecondLevel {
  std::vector<double> next_shot_values;
  int simulations = 0;
};
SecondLevel PlanNextShots(const table::TableGeometry& table, const physics::ModelParameters& params,
                          const std::vector<Execution>& executions, std::size_t candidates,
                          int samples, const ChoiceOptions& options, batch::ThreadPool& pool);

// Of `places` for the cue ball on `balls` (whose cue ball is moved there), the one whose next
// shot PlanNextShot values best (ties to the earlier), looking at the first
// options.position_places; the first when there are none to compare.
Eigen::Vector2d BestPlaceForNext(const table::TableGeometry& table,
                                 const physics::ModelParameters& params,
                                 const std::vector<table::SceneBall>& balls,
                                 const std::vector<Eigen::Vector2d>& places,
                                 const ChoiceOptions& options, batch::ThreadPool& pool,
                                 int* simulations = nullptr);

}  // namespace billiard::choice
