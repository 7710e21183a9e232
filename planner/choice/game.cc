#include "planner/choice/game.h"

#include <algorithm>
#include <cmath>

#include "sim/model_choice/model_choice.h"
#include "sim/table/rack.h"

namespace billiard::choice {

namespace {

// The execution noise's stream, apart from the choice's samples (which use the seed itself).
constexpr std::uint64_t kExecutionStream = 0x6578656375746521ull;
// A placed or respotted ball stays this far clear of the others [m].
constexpr double kClearance = 2e-3;
// The respotted 9 moves toward the foot rail in steps of this [m] until it is free.
constexpr double kRespotStep = 5e-3;

Eigen::Vector2d Position(const table::SceneBall& b) { return b.state.segment<2>(physics::kX); }

bool Has(const std::vector<table::SceneBall>& balls, int id) {
  return std::any_of(balls.begin(), balls.end(), [&](const auto& b) { return b.id == id; });
}

// The 9 back on the foot spot, or the nearest free place behind it toward the foot rail.
void RespotNine(const table::TableGeometry& table, double radius,
                std::vector<table::SceneBall>* balls) {
  table::SceneBall nine;
  nine.id = 9;
  nine.state.segment<2>(physics::kX) =
      table::FreeSpotFrom(table, radius, *balls, {0.75 * table.length, 0.5 * table.width},
                          {kRespotStep, 0.0}, kClearance);
  balls->push_back(nine);
}

bool Cleared(Rules rules, const std::vector<table::SceneBall>& balls, bool nine_potted_legally) {
  if (LegalTargets(Rules::kAny, balls).empty()) return true;
  return rules == Rules::kNineBall && nine_potted_legally;
}

// The break: the cue ball rolling at the ball nearest it.
physics::CueStroke BreakStroke(const std::vector<table::SceneBall>& balls, double speed) {
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

ChoiceResult Decide(const table::TableGeometry& table, const physics::ModelParameters& params,
                    const std::vector<table::SceneBall>& balls, const GameOptions& options,
                    bool ball_in_hand, int shot, batch::ThreadPool& pool) {
  ChoiceOptions choice = options.choice;
  choice.seed = SampleSeed(options.choice.seed, static_cast<std::uint64_t>(shot));
  choice.lookahead = options.policy == Policy::kOurs && options.choice.lookahead;
  if (options.policy == Policy::kEasiestLooking) {
    return ChooseEasiestLooking(table, params, balls, choice, ball_in_hand);
  }
  if (ball_in_hand) return ChooseWithBallInHand(table, params, balls, choice, pool, options.placements);
  return ChooseShot(table, params, balls, choice, pool);
}

}  // namespace

const char* PolicyName(Policy policy) {
  switch (policy) {
    case Policy::kOurs: return "ours";
    case Policy::kNoLookahead: return "no-lookahead";
    case Policy::kEasiestLooking: return "easiest-looking";
  }
  return "ours";
}

GameRecord PlayGame(const table::TableGeometry& table, const physics::ModelParameters& params,
                    std::vector<table::SceneBall> balls, const GameOptions& options,
                    batch::ThreadPool& pool) {
  GameRecord game;
  GameSummary& sum = game.summary;
  const auto motion = model_choice::TableMotion(params);
  const double radius = params.ball.radius;
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
    physics::CueStroke stroke;
    const bool breaking = options.break_shot && n == 0 && !ball_in_hand;
    if (breaking) {
      rec.break_shot = true;
      rec.status = "break";
      stroke = BreakStroke(balls, options.break_speed);
    } else {
      const ChoiceResult choice = Decide(table, params, balls, options, ball_in_hand, n, pool);
      rec.status = ChoiceStatusName(choice.status);
      rec.decision_us = choice.decision_us;
      decisions.push_back(choice.decision_us);
      if (choice.cue_placement) {
        rec.cue_placement = choice.cue_placement;
        balls = WithCueBallAt(balls, *choice.cue_placement);
      }
      if (const Candidate* c = choice.chosen()) {
        rec.ball = c->plan.ball;
        rec.pocket = c->plan.pocket;
        rec.kind = pot::ShotKindName(c->plan.kind);
        rec.predicted = c->finalist ? c->reported().probability : -1.0;
        rec.likely = choice.likely;
        stroke = c->plan.stroke;
      } else if (choice.fallback) {
        stroke = *choice.fallback;
      } else {
        break;  // nothing to play: an invalid scene or an empty table
      }
    }
    const std::vector<int> legal_first = LegalTargets(options.choice.rules, balls);
    NormalStream normal(SampleSeed(options.seed + kExecutionStream, static_cast<std::uint64_t>(n)));
    const physics::CueStroke played =
        params::Perturbed(stroke, options.execution, radius, [&] { return normal.Next(); });
    const StrokeResult result = PlayToRest(table, params, balls, played, motion);
    ++sum.shots;
    rec.first_contact = result.first_contact;
    for (const auto& [id, pocket] : result.pocketed) rec.potted.push_back(id);
    std::sort(rec.potted.begin(), rec.potted.end());
    if (!result.struck) {
      rec.foul = true;
      rec.foul_reason = "miscue";
    } else if (result.scratch) {
      rec.foul = true;
      rec.foul_reason = "scratch";
    } else if (result.first_contact < 0) {
      rec.foul = true;
      rec.foul_reason = "no contact";
    } else if (options.choice.rules == Rules::kNineBall && !rec.break_shot &&
               !legal_first.empty() && result.first_contact != legal_first.front()) {
      rec.foul = true;
      rec.foul_reason = "first contact " + std::to_string(result.first_contact) + ", not the lowest " +
                        std::to_string(legal_first.front());
    }
    if (rec.ball >= 0) {
      ++sum.attempts;
      rec.called_potted = !rec.foul && LegalPot(result, rec.ball, rec.pocket);
      sum.pots += rec.called_potted;
    }
    balls = result.rest;
    bool nine_legal = false;
    if (rec.foul) {
      ++sum.fouls;
      if (options.choice.rules == Rules::kNineBall &&
          std::find(rec.potted.begin(), rec.potted.end(), 9) != rec.potted.end()) {
        RespotNine(table, radius, &balls);
      }
    } else {
      sum.balls_potted += static_cast<int>(rec.potted.size());
      nine_legal = std::find(rec.potted.begin(), rec.potted.end(), 9) != rec.potted.end();
    }
    game.shots.push_back(rec);
    if (Cleared(options.choice.rules, balls, nine_legal)) {
      sum.cleared = true;
      break;
    }
    ball_in_hand = rec.foul;
    new_visit = rec.foul || rec.potted.empty();
    if (new_visit && options.single_visit) break;
    if (new_visit) ++visit;
  }
  sum.run_out = sum.cleared && sum.visits == 1;
  if (!decisions.empty()) {
    std::sort(decisions.begin(), decisions.end());
    sum.median_decision_us = decisions[decisions.size() / 2];
  }
  game.final_balls = balls;
  return game;
}

}  // namespace billiard::choice
