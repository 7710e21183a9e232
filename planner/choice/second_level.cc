#include "planner/choice/second_level.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "planner/choice/candidates.h"
#include "planner/choice/scene_balls.h"
#include "sim/rules/rules.h"

namespace billiard::choice {

namespace {

// The second level's seed stream, apart from the first level's and the confirmation's samples.
constexpr std::uint64_t kSecondLevelStream = 0x6e6578742073686full;

// The plan with the wider heading window (its narrower side) first: the more forgiving pot.
bool WiderWindow(const pot::PotPlan& a, const pot::PotPlan& b) {
  return std::min(a.margin_left_deg, a.margin_right_deg) >
         std::min(b.margin_left_deg, b.margin_right_deg);
}

// Whether `a` and `b` hold the same balls (in the same order, as the table leaves them), each
// within `radius` of its place in the other.
bool SameTable(const std::vector<table::SceneBall>& a, const std::vector<table::SceneBall>& b,
               double radius) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].id != b[i].id || (Position(a[i]) - Position(b[i])).norm() > radius) return false;
  }
  return true;
}

// The first cluster of `outcomes` whose representative is `rest`'s table, else a new one.
int ClusterOf(const std::vector<table::SceneBall>& rest, double radius, Outcomes* outcomes) {
  for (std::size_t c = 0; c < outcomes->states.size(); ++c) {
    if (SameTable(outcomes->states[c], rest, radius)) return static_cast<int>(c);
  }
  outcomes->states.push_back(rest);
  return static_cast<int>(outcomes->states.size()) - 1;
}

// Candidate `clusters`' (one a potting execution) `most` largest clusters, ties to the earlier.
std::vector<int> LargestClusters(const std::vector<int>& clusters, std::size_t cluster_count,
                                 int most) {
  std::vector<int> size(cluster_count, 0);
  for (int c : clusters) {
    if (c >= 0) ++size[c];
  }
  std::vector<int> order;
  for (std::size_t c = 0; c < cluster_count; ++c) {
    if (size[c] > 0) order.push_back(static_cast<int>(c));
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return size[a] > size[b]; });
  if (static_cast<int>(order.size()) > most) order.resize(most);
  return order;
}

// Of `valued` clusters, the one whose cue ball lies nearest the cue ball of `state`.
int NearestValued(const std::vector<table::SceneBall>& state, const std::vector<int>& valued,
                  const Outcomes& outcomes) {
  const table::SceneBall* cue = FindBall(state, 0);
  int nearest = valued.front();
  double best = std::numeric_limits<double>::infinity();
  for (int c : valued) {
    const table::SceneBall* other = FindBall(outcomes.states[c], 0);
    if (!cue || !other) continue;
    const double d = (Position(*cue) - Position(*other)).norm();
    if (d < best) {
      best = d;
      nearest = c;
    }
  }
  return nearest;
}

// The mean over candidate `clusters`' potting executions of the value of their cluster, or of
// the nearest of `valued` (its valued clusters) when theirs was not; 0 when none potted.
double MeanNextValue(const std::vector<int>& clusters, const std::vector<int>& valued,
                     const std::vector<double>& cluster_values, const Outcomes& outcomes) {
  double sum = 0.0;
  int potted = 0;
  for (int c : clusters) {
    if (c < 0) continue;
    ++potted;
    const bool was_valued = std::find(valued.begin(), valued.end(), c) != valued.end();
    sum += cluster_values[was_valued ? c : NearestValued(outcomes.states[c], valued, outcomes)];
  }
  return potted > 0 ? sum / potted : 0.0;
}

}  // namespace

NextShotValue PlanNextShot(const table::TableGeometry& table,
                           const physics::ModelParameters& params,
                           const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
                           batch::ThreadPool& pool) {
  if (rules::RulesetOf(options.rules).RackOver(balls)) return {1.0, 0};
  if (!FindBall(balls, 0)) return {0.0, 0};
  ChoiceOptions next = options;
  next.kinds = options.next_kinds;
  next.seed = options.seed + kSecondLevelStream;
  std::vector<pot::PotPlan> plans = PlanCandidates(table, params, balls, next, pool);
  NextShotValue result;
  for (const pot::PotPlan& plan : plans) result.simulations += plan.simulations;
  std::stable_sort(plans.begin(), plans.end(), WiderWindow);
  if (static_cast<int>(plans.size()) > options.next_plans) plans.resize(options.next_plans);
  std::vector<const pot::PotPlan*> pointers;
  for (const pot::PotPlan& plan : plans) pointers.push_back(&plan);
  const std::vector<Execution> executions =
      ExecuteAll(table, params, balls, pointers, options.next_samples, next, {}, false, pool);
  result.simulations += static_cast<int>(executions.size());
  for (std::size_t k = 0; k < plans.size(); ++k) {
    const std::vector<Execution> own(executions.begin() + k * options.next_samples,
                                     executions.begin() + (k + 1) * options.next_samples);
    result.value = std::max(result.value, PotRateOf(own).probability);
  }
  return result;
}

Outcomes ClusterOutcomes(const std::vector<Execution>& executions, std::size_t candidates,
                         int samples, double radius) {
  Outcomes outcomes;
  outcomes.cluster_of.assign(candidates, std::vector<int>(samples, -1));
  for (std::size_t k = 0; k < candidates; ++k) {
    for (int s = 0; s < samples; ++s) {
      const Execution& e = executions[k * samples + s];
      if (e.potted) outcomes.cluster_of[k][s] = ClusterOf(e.rest, radius, &outcomes);
    }
  }
  return outcomes;
}

SecondLevel PlanNextShots(const table::TableGeometry& table, const physics::ModelParameters& params,
                          const std::vector<Execution>& executions, std::size_t candidates,
                          int samples, const ChoiceOptions& options, batch::ThreadPool& pool) {
  const Outcomes outcomes = ClusterOutcomes(executions, candidates, samples, options.cluster_radius);
  std::vector<std::vector<int>> valued(candidates);
  std::vector<bool> to_value(outcomes.states.size(), false);
  for (std::size_t k = 0; k < candidates; ++k) {
    valued[k] = LargestClusters(outcomes.cluster_of[k], outcomes.states.size(),
                                options.second_level_states);
    for (int c : valued[k]) to_value[c] = true;
  }
  SecondLevel result;
  std::vector<double> cluster_values(outcomes.states.size(), 0.0);
  for (std::size_t c = 0; c < outcomes.states.size(); ++c) {
    if (!to_value[c]) continue;
    const NextShotValue next = PlanNextShot(table, params, outcomes.states[c], options, pool);
    cluster_values[c] = next.value;
    result.simulations += next.simulations;
  }
  for (std::size_t k = 0; k < candidates; ++k) {
    result.next_shot_values.push_back(
        valued[k].empty() ? 0.0
                          : MeanNextValue(outcomes.cluster_of[k], valued[k], cluster_values, outcomes));
  }
  return result;
}

Eigen::Vector2d BestPlaceForNext(const table::TableGeometry& table,
                                 const physics::ModelParameters& params,
                                 const std::vector<table::SceneBall>& balls,
                                 const std::vector<Eigen::Vector2d>& places,
                                 const ChoiceOptions& options, batch::ThreadPool& pool,
                                 int* simulations) {
  std::size_t best = 0;
  double best_value = -1.0;
  const std::size_t compared =
      std::min(places.size(), static_cast<std::size_t>(std::max(options.position_places, 0)));
  for (std::size_t i = 0; compared > 1 && i < compared; ++i) {
    const NextShotValue next =
        PlanNextShot(table, params, WithCueBallAt(balls, places[i]), options, pool);
    if (simulations) *simulations += next.simulations;
    if (next.value > best_value) {
      best_value = next.value;
      best = i;
    }
  }
  return places.at(best);
}

}  // namespace billiard::choice
