#include "planner/choice/candidates.h"

#include <utility>

#include "sim/rules/rules.h"

namespace billiard::choice {

std::vector<pot::PotPlan> PlanCandidates(const table::TableGeometry& table,
                                         const physics::ModelParameters& params,
                                         const std::vector<table::SceneBall>& balls,
                                         const ChoiceOptions& options, batch::ThreadPool& pool) {
  std::vector<pot::PotRequest> requests;
  for (int ball : rules::LegalTargets(options.rules, balls)) {
    for (const table::Pocket& pocket : table.pockets) {
      for (pot::ShotKind kind : options.kinds) {
        pot::PotRequest r;
        r.ball = ball;
        r.pocket = pocket.name;
        r.kind = kind;
        requests.push_back(r);
      }
    }
  }
  const pot::PotOptions ranking = RankingPotOptions(options);
  auto plans = pool.Map(requests.size(), [&](std::size_t i) {
    return pot::PlanPot(table, params, balls, requests[i], ranking);
  });
  std::vector<pot::PotPlan> ok;
  for (auto& p : plans) {
    if (p.ok() && p.value->status == pot::PotStatus::kOk) ok.push_back(std::move(*p.value));
  }
  return ok;
}

std::vector<const pot::PotPlan*> PlansOf(const std::vector<Candidate>& candidates,
                                         const std::vector<std::size_t>& which) {
  std::vector<const pot::PotPlan*> plans;
  for (std::size_t i : which) plans.push_back(&candidates[i].plan);
  return plans;
}

}  // namespace billiard::choice
