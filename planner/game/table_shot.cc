#include "planner/game/table_shot.h"

#include <algorithm>

#include "planner/choice/scene_balls.h"
#include "planner/pot/pot_planner.h"

namespace billiard::game {

std::optional<physics::CueStroke> PlayerStroke(const players::Player& player,
                                               const players::Turn& turn,
                                               choice::ChoiceOptions options, std::uint64_t seed,
                                               batch::ThreadPool& pool,
                                               std::vector<table::SceneBall>* balls,
                                               ShotRecord* rec) {
  options.seed = seed;
  // A rack's record states no margin: the chosen pot's is left as ranked.
  options.state_margin = false;
  const choice::ChoiceResult decided = player.Decide(turn, options, pool);
  rec->status = choice::ChoiceStatusName(decided.status);
  rec->reason = decided.reason;
  rec->decision_us = decided.decision_us;
  if (decided.cue_placement) {
    rec->cue_placement = decided.cue_placement;
    *balls = choice::WithCueBallAt(*balls, *decided.cue_placement);
  }
  rec->safety = decided.safety.has_value();
  rec->attempt_win = decided.attempt_win;
  rec->safety_win = decided.safety_win;
  rec->likely = decided.likely;
  if (const choice::Candidate* c = decided.chosen(); c && !rec->safety) {
    rec->ball = c->plan.ball;
    rec->pocket = c->plan.pocket;
    rec->kind = pot::ShotKindName(c->plan.kind);
    rec->predicted = c->finalist ? c->reported().probability : -1.0;
    rec->clearance = c->plan.clearance;
  }
  if (const physics::CueStroke* stroke = decided.stroke()) {
    rec->stroke = *stroke;
    return *stroke;
  }
  return std::nullopt;
}

choice::StrokeResult ExecuteWithNoise(const table::TableGeometry& table,
                                      const physics::ModelParameters& params,
                                      const std::vector<table::SceneBall>& balls,
                                      const physics::CueStroke& stroke,
                                      const params::ExecutionNoise& noise, std::uint64_t seed,
                                      const choice::Motion& motion,
                                      std::vector<table::TableEvent>* events) {
  choice::NormalStream normal(seed);
  const physics::CueStroke played =
      params::Perturbed(stroke, noise, params.ball.radius, [&] { return normal.Next(); });
  return choice::PlayToRest(table, params, balls, played, motion, events);
}

rules::Shot ShotOf(const rules::Constraints& constraints, const ShotRecord& rec,
                   const choice::StrokeResult& result) {
  std::vector<std::pair<int, std::string>> pocketed = result.pocketed;
  std::sort(pocketed.begin(), pocketed.end());
  rules::Shot shot;
  shot.constraints = constraints;
  shot.break_shot = rec.break_shot;
  shot.struck = result.struck;
  shot.first_contact = result.first_contact;
  for (const auto& [id, pocket] : pocketed) {
    shot.potted.push_back(id);
    shot.pockets.push_back(pocket);
  }
  shot.scratch = result.scratch;
  shot.object_balls_left = static_cast<int>(rules::ObjectBalls(result.rest).size());
  shot.to_rail_after_contact = result.to_rail_after_contact;
  shot.call = {rec.ball, rec.pocket};
  return shot;
}

}  // namespace billiard::game
