#include "planner/choice/position_play.h"

#include <algorithm>
#include <utility>

#include "planner/choice/placements.h"
#include "planner/choice/screening.h"

namespace billiard::choice {

std::vector<Candidate> PositionCandidates(const table::TableGeometry& table,
                                          const physics::ModelParameters& params,
                                          const std::vector<table::SceneBall>& balls,
                                          std::vector<Candidate> screened,
                                          const ChoiceOptions& options, batch::ThreadPool& pool) {
  std::stable_sort(screened.begin(), screened.end(), ScreenedBetter);
  std::vector<pot::PotRequest> requests;
  for (const Candidate& c : screened) {
    if (static_cast<int>(requests.size()) >= options.position_plans) break;
    if (c.screen_probability <= 0) break;
    std::vector<table::SceneBall> after;
    for (const table::SceneBall& b : balls) {
      if (b.id != c.plan.ball) after.push_back(b);
    }
    const std::vector<Placement> places =
        CandidatePlacements(table, params.ball.radius, after, options);
    if (places.empty()) continue;
    pot::PotRequest r;
    r.ball = c.plan.ball;
    r.pocket = c.plan.pocket;
    r.kind = c.plan.kind;
    r.cue_target = pot::CueTarget{places.front().place, options.position_radius};
    requests.push_back(r);
  }
  auto plans = pool.Map(requests.size(), [&](std::size_t i) {
    return pot::PlanPot(table, params, balls, requests[i], options.pot);
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
