#include "planner/choice/position_play.h"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>

#include "planner/choice/placements.h"
#include "planner/choice/screening.h"
#include "planner/choice/second_level.h"

namespace billiard::choice {

namespace {

// Where position play sends the cue ball on `after` (the table without the ball potted): the
// best-looking place (CandidatePlacements), or with the second level the place of the best
// looking few whose next shot it values best; nothing when no place looks possible.
std::optional<Eigen::Vector2d> TargetFor(const table::TableGeometry& table,
                                         const physics::ModelParameters& params,
                                         const std::vector<table::SceneBall>& after,
                                         const ChoiceOptions& options, batch::ThreadPool& pool) {
  const std::vector<Placement> places =
      CandidatePlacements(table, params.ball.radius, after, options);
  if (places.empty()) return std::nullopt;
  if (!options.second_level) return places.front().place;
  std::vector<Eigen::Vector2d> points;
  for (const Placement& p : places) points.push_back(p.place);
  return BestPlaceForNext(table, params, after, points, options, pool);
}

}  // namespace

std::vector<Candidate> PositionCandidates(const table::TableGeometry& table,
                                          const physics::ModelParameters& params,
                                          const std::vector<table::SceneBall>& balls,
                                          std::vector<Candidate> screened,
                                          const ChoiceOptions& options, batch::ThreadPool& pool) {
  std::stable_sort(screened.begin(), screened.end(), ScreenedBetter);
  std::vector<pot::PotRequest> requests;
  // The cue ball's target by the ball potted: the pots of one ball leave the same table.
  std::map<int, std::optional<Eigen::Vector2d>> targets;
  for (const Candidate& c : screened) {
    if (static_cast<int>(requests.size()) >= options.position_plans) break;
    if (c.screen_probability <= 0) break;
    std::vector<table::SceneBall> after;
    for (const table::SceneBall& b : balls) {
      if (b.id != c.plan.ball) after.push_back(b);
    }
    auto known = targets.find(c.plan.ball);
    if (known == targets.end()) {
      known = targets.emplace(c.plan.ball, TargetFor(table, params, after, options, pool)).first;
    }
    if (!known->second) continue;
    pot::PotRequest r;
    r.ball = c.plan.ball;
    r.pocket = c.plan.pocket;
    r.kind = c.plan.kind;
    r.cue_target = pot::CueTarget{*known->second, options.position_radius};
    requests.push_back(r);
  }
  const pot::PotOptions ranking = RankingPotOptions(options);
  auto plans = pool.Map(requests.size(), [&](std::size_t i) {
    return pot::PlanPot(table, params, balls, requests[i], ranking);
  });
  std::vector<Candidate> played;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    if (!plans[i].ok() || plans[i].value->status != pot::PotStatus::kOk) continue;
    Candidate c;
    c.plan = std::move(*plans[i].value);
    c.position_target = requests[i].cue_target->point;
    played.push_back(std::move(c));
  }
  return played;
}

}  // namespace billiard::choice
