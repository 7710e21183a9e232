#include "planner/game/game.h"

#include <algorithm>

#include "planner/choice/monte_carlo.h"
#include "planner/choice/scene_balls.h"
#include "sim/model_choice/model_choice.h"
#include "sim/rules/rules.h"

namespace billiard::game {

namespace {

bool Has(const std::vector<table::SceneBall>& balls, int id) {
  return std::any_of(balls.begin(), balls.end(), [&](const auto& b) { return b.id == id; });
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

void Summarize(std::vector<double> decisions, const std::vector<ShotRecord>& shots,
               GameSummary* sum) {
  sum->cleared = sum->end == GameEnd::kCleared;
  sum->run_out = rules::RunOut(sum->cleared, sum->visits, rules::FirstVisitAfterBreak(shots));
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
      stroke = SetUpBreak(table, params.ball.radius, options.opening, &balls);
      rec.cue_placement = choice::Position(balls.front());
      rec.stroke = stroke;
    } else {
      // Alone at the table (players::Turn::alone): no safety is weighed.
      const players::Turn turn{table, params, balls, constraints, true};
      stroke = PlayerStroke(*options.player, turn, options.choice,
                            choice::SampleSeed(options.choice.seed, static_cast<std::uint64_t>(n)),
                            pool, &balls, &rec);
      decisions.push_back(rec.decision_us);
    }
    if (!stroke) {  // an invalid scene: said, not played
      sum.end = GameEnd::kNoStroke;
      sum.end_reason = rec.status + ": " + rec.reason;
      break;
    }
    const choice::StrokeResult result = ExecuteWithNoise(
        table, params, balls, *stroke, options.execution,
        choice::SampleSeed(options.seed + kExecutionStream, static_cast<std::uint64_t>(n)),
        motion);
    const rules::Shot shot = ShotOf(constraints, rec, result);
    rec.potted = shot.potted;
    const rules::Judgement judgement = ruleset.Judge(table, shot);
    Record(result, judgement, &rec, &sum);
    balls = result.rest;
    rules::PlaceRespotted(table, params.ball.radius, judgement.respots, kRespotStep, kRespotClearance,
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
  Summarize(std::move(decisions), game.shots, &sum);
  game.final_balls = balls;
  return game;
}

}  // namespace billiard::game
