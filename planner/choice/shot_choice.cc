#include "planner/choice/shot_choice.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "planner/choice/candidates.h"
#include "planner/choice/monte_carlo.h"
#include "planner/choice/position_play.h"
#include "planner/choice/race.h"
#include "planner/choice/screening.h"
#include "planner/choice/second_level.h"
#include "sim/model_choice/model_choice.h"

namespace billiard::choice {

namespace {

// The confirmation's seed stream, apart from the choice's own samples.
constexpr std::uint64_t kConfirmStream = 0x636f6e6669726d21ull;

// Step 1: every legal pot that plans, a candidate.
void AddCandidates(const table::TableGeometry& table, const physics::ModelParameters& params,
                   const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
                   batch::ThreadPool& pool, ChoiceResult* result) {
  for (pot::PotPlan& plan : PlanCandidates(table, params, balls, options, pool)) {
    result->simulations += plan.simulations;
    Candidate c;
    c.plan = std::move(plan);
    result->candidates.push_back(std::move(c));
  }
}

// Step 2: every candidate screened on the closed form; with the lookahead the best few planned
// again with position play (the same pot leaving the cue ball where the next shot looks
// easiest) and screened too; all in the screening's order.
void ScreenCandidates(const table::TableGeometry& table, const physics::ModelParameters& params,
                      const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
                      batch::ThreadPool& pool, ChoiceResult* result) {
  std::vector<Candidate>& candidates = result->candidates;
  std::vector<std::size_t> plain(candidates.size());
  for (std::size_t i = 0; i < plain.size(); ++i) plain[i] = i;
  result->simulations += Screen(table, params, balls, plain, options, pool, &candidates);
  if (options.lookahead && options.position_plans > 0) {
    std::vector<Candidate> played =
        PositionCandidates(table, params, balls, candidates, options, pool);
    std::vector<std::size_t> added;
    for (Candidate& c : played) {
      result->simulations += c.plan.simulations;
      added.push_back(candidates.size());
      candidates.push_back(std::move(c));
    }
    result->simulations += Screen(table, params, balls, added, options, pool, &candidates);
  }
  std::stable_sort(candidates.begin(), candidates.end(), ScreenedBetter);
}

// The second level (second_level.h) on the samples every finalist played: a finalist the race
// stopped played fewer, and each is valued on the same samples' outcomes. The race itself
// stopped finalists on the closed-form lookahead, which costs nothing per sample.
SecondLevel PlanSecondLevel(const table::TableGeometry& table,
                            const physics::ModelParameters& params,
                            const std::vector<std::vector<Execution>>& runs,
                            const ChoiceOptions& options, batch::ThreadPool& pool,
                            ChoiceResult* result) {
  if (!options.lookahead || !options.second_level || runs.empty()) return {};
  std::size_t common = runs.front().size();
  for (const std::vector<Execution>& run : runs) common = std::min(common, run.size());
  std::vector<Execution> shared;
  for (const std::vector<Execution>& run : runs) {
    shared.insert(shared.end(), run.begin(), run.begin() + common);
  }
  SecondLevel planned = PlanNextShots(table, params, shared, runs.size(),
                                      static_cast<int>(common), options, pool);
  result->simulations += planned.simulations;
  return planned;
}

// Steps 3 and 4: the finalists raced on the full model (race.h), with the lookahead (its next
// shot planned by the second level, or in closed form without it), scored; the finalists first,
// the others after them in screening order.
void PlayFinalists(const table::TableGeometry& table, const physics::ModelParameters& params,
                   const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
                   batch::ThreadPool& pool, ChoiceResult* result) {
  std::vector<Candidate>& candidates = result->candidates;
  std::vector<std::size_t> finalists;
  for (std::size_t i = 0; i < candidates.size() && static_cast<int>(i) < options.finalists; ++i) {
    finalists.push_back(i);
  }
  const std::vector<std::vector<Execution>> runs =
      RaceFinalists(table, params, balls, PlansOf(candidates, finalists), options,
                    model_choice::TableMotion(params), pool);
  const SecondLevel planned = PlanSecondLevel(table, params, runs, options, pool, result);
  for (std::size_t f = 0; f < finalists.size(); ++f) {
    Candidate& c = candidates[finalists[f]];
    c.finalist = true;
    const int samples = static_cast<int>(runs[f].size());
    result->simulations += samples;
    Tally tally = TallyOf(runs[f], 0, samples);
    if (!planned.next_shot_values.empty()) tally.next_shot_value = planned.next_shot_values[f];
    c.full = tally.pots;
    c.next_shot_value = tally.next_shot_value;
    c.score = Score(tally, options.lookahead);
  }
  // Those that ran the race furthest first (the one left, or those that ran it to the end),
  // then by score.
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    if (a.finalist != b.finalist) return a.finalist;
    if (!a.finalist) return false;
    if (a.full.samples != b.full.samples) return a.full.samples > b.full.samples;
    return a.score > b.score;
  });
}

}  // namespace

ChoiceResult ChooseUnconfirmed(const table::TableGeometry& table,
                               const physics::ModelParameters& params,
                               const std::vector<table::SceneBall>& balls,
                               const ChoiceOptions& options, batch::ThreadPool& pool) {
  if (auto refusal = Unplayable(table, params, balls, options.rules)) return *refusal;
  ChoiceResult result;
  AddCandidates(table, params, balls, options, pool, &result);
  if (result.candidates.empty()) {
    NoPlan(table, params.ball.radius, balls, options.rules, options.pot.robot,
           "no pot of a legal ball plans (every route blocked, too thin, out of reach or cue_blocked)", &result);
    return result;
  }
  ScreenCandidates(table, params, balls, options, pool, &result);
  PlayFinalists(table, params, balls, options, pool, &result);
  result.status = ChoiceStatus::kOk;
  return result;
}

void Confirm(const table::TableGeometry& table, const physics::ModelParameters& params,
             const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
             batch::ThreadPool& pool, ChoiceResult* result) {
  if (result->status != ChoiceStatus::kOk) return;
  Candidate& chosen = result->candidates.front();
  if (options.confirm_samples > 0) {
    ChoiceOptions fresh = options;
    fresh.seed = options.seed + kConfirmStream;
    chosen.confirmed = ConfirmToPrecision(table, params, balls, chosen.plan, fresh,
                                          model_choice::TableMotion(params), pool);
    result->simulations += chosen.confirmed.samples;
  }
  // Its margin was walked to rank it (RankingPotOptions); stated, it is walked in full.
  if (options.state_margin) {
    result->simulations += pot::StateMargins(table, params, balls, &chosen.plan, options.pot);
  }
  result->likely = chosen.reported().probability >= options.likely;
  if (!result->likely) {
    result->reason = "no shot is likely: the best pots with probability " +
                     std::to_string(chosen.reported().probability) +
                     "; playing the best expected one";
  }
}

ChoiceResult ChooseShot(const table::TableGeometry& table, const physics::ModelParameters& params,
                        const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
                        batch::ThreadPool& pool) {
  const auto start = std::chrono::steady_clock::now();
  ChoiceResult result = ChooseUnconfirmed(table, params, balls, options, pool);
  Confirm(table, params, balls, options, pool, &result);
  result.decision_us = MicrosecondsSince(start);
  return result;
}

}  // namespace billiard::choice
