#include "planner/game/game.h"

#include <algorithm>
#include <cmath>

#include "planner/choice/monte_carlo.h"
#include "planner/choice/scene_balls.h"
#include "planner/pot/pot_planner.h"
#include "sim/model_choice/model_choice.h"
#include "sim/rules/rules.h"

namespace billiard::game {

namespace {

// The execution noise's stream, apart from the choice's samples (which use the seed itself).
constexpr std::uint64_t kExecutionStream = 0x6578656375746521ull;
// A respotted ball stays this far clear of the others [m].
constexpr double kClearance = 2e-3;
// A respotted ball moves along its direction in steps of this [m] until it is free.
constexpr double kRespotStep = 5e-3;

bool Has(const std::vector<table::SceneBall>& balls, int id) {
  return std::any_of(balls.begin(), balls.end(), [&](const auto& b) { return b.id == id; });
}

// The break: the cue ball rolling at the ball nearest it.
physics::CueStroke BreakStroke(const std::vector<table::SceneBall>& balls, double speed) {
  using choice::Position;
  const table::SceneBall* cue = nullptr;
  for (const auto& b : balls) {
    if (b.id == 0) cue = &b;
  }
  const table::SceneBall* nearest = nullptr;
  for (const auto& b : balls) {
    if (b.id == 0) continue;
    if (!nearest || (Position(b) - Position(*cue)).norm() <
                        (Position(*nearest) - Position(*cue)).norm()) {
      nearest = &b;
    }
  }
  const Eigen::Vector2d d = Position(*nearest) - Position(*cue);
  physics::CueStroke s;
  s.speed = speed;
  s.heading = std::atan2(d.y(), d.x());
  return s;
}

// The player's stroke for shot n, its samples seeded from the choice's seed and n: the cue
// ball placed first when the player says where, the decision and the call recorded in `rec`;
// none when there is nothing to play.
std::optional<physics::CueStroke> PlayersStroke(const table::TableGeometry& table,
                                                const physics::ModelParameters& params,
                                                const rules::Constraints& constraints,
                                                const GameOptions& options, int n,
                                                batch::ThreadPool& pool,
                                                std::vector<table::SceneBall>* balls,
                                                ShotRecord* rec) {
  choice::ChoiceOptions choice = options.choice;
  choice.seed = choice::SampleSeed(options.choice.seed, static_cast<std::uint64_t>(n));
  const choice::ChoiceResult decided =
      options.player->Decide({table, params, *balls, constraints}, choice, pool);
  rec->status = choice::ChoiceStatusName(decided.status);
  rec->reason = decided.reason;
  rec->decision_us = decided.decision_us;
  if (decided.cue_placement) {
    rec->cue_placement = decided.cue_placement;
    *balls = choice::WithCueBallAt(*balls, *decided.cue_placement);
  }
  if (const choice::Candidate* c = decided.chosen()) {
    rec->ball = c->plan.ball;
    rec->pocket = c->plan.pocket;
    rec->kind = pot::ShotKindName(c->plan.kind);
    rec->predicted = c->finalist ? c->reported().probability : -1.0;
    rec->likely = decided.likely;
    rec->clearance = c->plan.clearance;
  }
  if (const physics::CueStroke* stroke = decided.stroke()) {
    rec->stroke = *stroke;
    return *stroke;
  }
  return std::nullopt;
}

// Shot n's stroke played on the table with the table's noise, from a stream of its own.
choice::StrokeResult Execute(const table::TableGeometry& table,
                             const physics::ModelParameters& params,
                             const std::vector<table::SceneBall>& balls,
                             const physics::CueStroke& stroke, const GameOptions& options, int n,
                             const choice::Motion& motion) {
  choice::NormalStream normal(
      choice::SampleSeed(options.seed + kExecutionStream, static_cast<std::uint64_t>(n)));
  const physics::CueStroke played = params::Perturbed(stroke, options.execution,
                                                      params.ball.radius,
                                                      [&] { return normal.Next(); });
  return choice::PlayToRest(table, params, balls, played, motion);
}

// What the referee sees of a shot played under `constraints`.
rules::Shot ShotOf(const rules::Constraints& constraints, bool break_shot,
                   const choice::StrokeResult& result, const std::vector<int>& potted) {
  rules::Shot shot;
  shot.constraints = constraints;
  shot.break_shot = break_shot;
  shot.struck = result.struck;
  shot.first_contact = result.first_contact;
  shot.potted = potted;
  shot.scratch = result.scratch;
  shot.object_balls_left = static_cast<int>(rules::ObjectBalls(result.rest).size());
  return shot;
}

// The shot's outcome and judgement into its record and the game's summary.
void Record(const choice::StrokeResult& result, const rules::Judgement& judgement,
            ShotRecord* rec, GameSummary* sum) {
  ++sum->shots;
  rec->first_contact = result.first_contact;
  rec->foul = judgement.foul;
  rec->foul_reason = judgement.foul_reason;
  if (rec->ball >= 0) {
    ++sum->attempts;
    rec->called_potted = !rec->foul && choice::LegalPot(result, rec->ball, rec->pocket);
    sum->pots += rec->called_potted;
  }
  if (rec->foul) {
    ++sum->fouls;
  } else {
    sum->balls_potted += static_cast<int>(rec->potted.size());
  }
}

// The object balls `result` dropped, in id order.
std::vector<int> PottedIds(const choice::StrokeResult& result) {
  std::vector<int> potted;
  for (const auto& [id, pocket] : result.pocketed) potted.push_back(id);
  std::sort(potted.begin(), potted.end());
  return potted;
}

void Summarize(std::vector<double> decisions, GameSummary* sum) {
  sum->cleared = sum->end == GameEnd::kCleared;
  sum->run_out = sum->cleared && sum->visits == 1;
  if (!decisions.empty()) {
    std::sort(decisions.begin(), decisions.end());
    sum->median_decision_us = decisions[decisions.size() / 2];
  }
}

}  // namespace

const char* GameEndName(GameEnd end) {
  switch (end) {
    case GameEnd::kCleared: return "cleared";
    case GameEnd::kShotLimit: return "shot_limit";
    case GameEnd::kVisitOver: return "visit_over";
    case GameEnd::kNoStroke: return "no_stroke";
  }
  return "no_stroke";
}

void DropHangingBalls(const table::TableGeometry& table, choice::StrokeResult* result) {
  std::vector<table::SceneBall> rest;
  for (const table::SceneBall& b : result->rest) {
    const table::Pocket* pocket = table.PocketPastMouth(choice::Position(b));
    if (!pocket) {
      rest.push_back(b);
    } else if (b.id == 0) {
      result->scratch = true;
    } else {
      result->pocketed.emplace_back(b.id, pocket->name);
    }
  }
  result->rest = std::move(rest);
}

GameRecord PlayGame(const table::TableGeometry& table, const physics::ModelParameters& params,
                    std::vector<table::SceneBall> balls, const GameOptions& options,
                    batch::ThreadPool& pool) {
  GameRecord game;
  GameSummary& sum = game.summary;
  const rules::Ruleset& ruleset = rules::RulesetOf(options.choice.rules);
  const auto motion = model_choice::TableMotion(params);
  bool ball_in_hand = options.ball_in_hand || !Has(balls, 0);
  int visit = 1;
  bool new_visit = true;
  std::vector<double> decisions;
  for (int n = 0; n < options.shot_limit; ++n) {
    if (new_visit) sum.visits = visit;
    ShotRecord rec;
    rec.number = n + 1;
    rec.visit = visit;
    rec.ball_in_hand = ball_in_hand;
    const rules::Constraints constraints{ball_in_hand, ruleset.LegalTargets(balls)};
    std::optional<physics::CueStroke> stroke;
    if (options.break_shot && n == 0 && !ball_in_hand) {
      rec.break_shot = true;
      rec.status = "break";
      stroke = BreakStroke(balls, options.break_speed);
      rec.stroke = stroke;
    } else {
      stroke = PlayersStroke(table, params, constraints, options, n, pool, &balls, &rec);
      decisions.push_back(rec.decision_us);
    }
    if (!stroke) {  // an invalid scene: said, not played
      sum.end = GameEnd::kNoStroke;
      sum.end_reason = rec.status + ": " + rec.reason;
      break;
    }
    choice::StrokeResult result = Execute(table, params, balls, *stroke, options, n, motion);
    DropHangingBalls(table, &result);
    rec.potted = PottedIds(result);
    const rules::Judgement judgement =
        ruleset.Judge(table, ShotOf(constraints, rec.break_shot, result, rec.potted));
    Record(result, judgement, &rec, &sum);
    balls = result.rest;
    rules::PlaceRespotted(table, params.ball.radius, judgement.respots, kRespotStep, kClearance,
                          &balls);
    game.shots.push_back(rec);
    if (judgement.rack_over) {
      sum.end = GameEnd::kCleared;
      break;
    }
    ball_in_hand = judgement.ball_in_hand;
    new_visit = judgement.turn_over;
    if (new_visit && options.single_visit) {
      sum.end = GameEnd::kVisitOver;
      break;
    }
    if (new_visit) ++visit;
  }
  Summarize(std::move(decisions), &sum);
  game.final_balls = balls;
  return game;
}

}  // namespace billiard::game
