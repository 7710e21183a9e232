#include "planner/node/choose_request.h"

#include <algorithm>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "planner/choice/monte_carlo.h"
#include "planner/node/ball_numbers.h"
#include "planner/node/break_request.h"
#include "planner/node/command_writing.h"
#include "planner/node/scene_at_rest.h"
#include "sim/rules/rules.h"
#include "sim/table/scene.h"
#include "sim/table/table_simulation.h"

namespace billiard::planner_node {

namespace {

// The balls a choice is made among: those of `latest` at rest, numbered (BallNumbers), less the
// object balls seen dropping; nullopt and `moving` set when a ball moves.
std::optional<std::vector<table::SceneBall>> ChoiceScene(
    const table_state_t& latest, const ball_state_t& cue, const table::TableGeometry& table,
    const physics::ModelParameters& params, const PlannerNodeOptions& options,
    std::unordered_map<int, int32_t>* message_id, std::string* moving) {
  const std::unordered_map<int32_t, int> number = BallNumbers(latest, cue.ball_id);
  auto balls = SceneAtRest(
      latest, options.max_ball_speed, cue.ball_id, [&](int32_t id) { return number.at(id); },
      message_id, moving);
  if (!balls) return std::nullopt;
  // An object ball seen further over a pocket's mouth or into a cushion than settling moves one
  // is dropping (the estimator's last frames of it): no ball to play.
  balls->erase(std::remove_if(balls->begin(), balls->end(),
                              [&](const table::SceneBall& b) {
                                return b.id != 0 &&
                                       !table.OnSurface(
                                           b.state.head<2>(),
                                           params.ball.radius - options.pot.settle_overlap);
                              }),
               balls->end());
  return balls;
}

// The choice's options for `q`: its rules, its samples seeded by its id, the node's pot options.
choice::ChoiceOptions ChoiceOptionsFor(const shot_request_t& q, const PlannerNodeOptions& node) {
  choice::ChoiceOptions options = node.choice;
  options.rules = RulesOf(q);
  options.seed = choice::SampleSeed(node.choice.seed, static_cast<std::uint64_t>(q.request_id));
  options.pot = node.pot;
  return options;
}

// The choice into `c`: the pot chosen with its confirmed probability, or the safety's or the
// fallback's stroke (no call); the cue ball's placement with ball in hand; refused as the choice
// refused.
cue_command_t WriteChoice(const choice::ChoiceResult& result,
                          const std::unordered_map<int, int32_t>& message_id, cue_command_t c) {
  switch (result.status) {
    case choice::ChoiceStatus::kInvalid:
      return Refusal(c, cue_command_t::STATUS_INVALID, result.reason);
    case choice::ChoiceStatus::kNoTarget:
      return Refusal(c, cue_command_t::STATUS_NO_SUCH_BALL, result.reason);
    case choice::ChoiceStatus::kOk:
    case choice::ChoiceStatus::kNoPlan:
      break;
  }
  if (result.cue_placement) {
    c.has_cue_placement = 1;
    c.start[0] = c.cue_placement[0] = result.cue_placement->x();
    c.start[1] = c.cue_placement[1] = result.cue_placement->y();
  }
  // A safety calls nothing: its stroke is written as the fallback's is, and said to be one.
  c.safety = result.safety ? 1 : 0;
  if (const choice::Candidate* chosen = result.safety ? nullptr : result.chosen()) {
    WritePot(chosen->plan, message_id, &c);
    c.object_ball_id = message_id.at(chosen->plan.ball);
    c.pocket = chosen->plan.pocket;
    c.success_probability = chosen->reported().probability;
    c.probability_stderr = chosen->reported().stderr_;
  } else {  // a safety, or kNoPlan's fallback, which at least hits the first legal ball
    WriteStroke(*result.stroke(), &c);
  }
  c.solve_us = result.decision_us;
  c.iterations = result.simulations;
  return Sendable(c);
}

}  // namespace

cue_command_t AnswerChoice(const shot_request_t& q, const ball_state_t& cue,
                           const table_state_t& latest, const table::TableGeometry& table,
                           const physics::ModelParameters& params,
                           const PlannerNodeOptions& options, const players::Player& player,
                           batch::ThreadPool& pool, cue_command_t c) {
  std::unordered_map<int, int32_t> message_id;
  std::string moving;
  auto balls = ChoiceScene(latest, cue, table, params, options, &message_id, &moving);
  if (!balls) return Refusal(c, cue_command_t::STATUS_NOT_AT_REST, moving);
  const choice::ChoiceOptions choosing = ChoiceOptionsFor(q, options);
  choice::ChoiceResult result;
  try {
    // What the camera saw, touching balls settled apart as a pot's are.
    *balls = table::SettledScene(table, params.ball.radius, std::move(*balls),
                                 options.pot.settle_overlap);
    const players::Turn turn{table, params, *balls,
                             {q.ball_in_hand != 0, rules::LegalTargets(choosing.rules, *balls)},
                             q.alone != 0};
    result = player.Decide(turn, choosing, pool);
  } catch (const std::exception& e) {
    return Refusal(c, cue_command_t::STATUS_INVALID, std::string("no choice: ") + e.what());
  }
  return WriteChoice(result, message_id, std::move(c));
}

}  // namespace billiard::planner_node
