#include "planner/game/match.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "planner/choice/monte_carlo.h"
#include "planner/choice/scene_balls.h"
#include "planner/game/match_summary.h"
#include "planner/players/players.h"
#include "sim/model_choice/model_choice.h"
#include "sim/rules/rack_state.h"
#include "sim/table/rack.h"

namespace billiard::game {

namespace {

// What every shot of a rack shares.
struct RackContext {
  const table::TableGeometry& table;
  const physics::ModelParameters& params;
  const MatchOptions& options;
  batch::ThreadPool& pool;
  choice::Motion motion;
  std::uint64_t seed;  // the rack's
};

// Whether `shot` potted its called ball in the called pocket.
bool CalledBallPotted(const rules::Shot& shot) {
  for (std::size_t i = 0; i < shot.potted.size(); ++i) {
    if (shot.potted[i] == shot.call.ball && shot.pockets[i] == shot.call.pocket) return true;
  }
  return false;
}

// The break, or the shooter's decision on the constraints the rack's state gives.
std::optional<physics::CueStroke> StrokeOf(const RackContext& c, int n,
                                           const rules::RackState& state,
                                           const rules::Constraints& constraints,
                                           std::vector<table::SceneBall>* balls,
                                           ShotRecord* rec) {
  if (state.shots == 0) {
    rec->break_shot = true;
    rec->status = "break";
    const physics::CueStroke stroke =
        SetUpBreak(c.table, c.params.ball.radius,
                   c.options.opening.value_or(StoredBreak(c.options.game)), balls);
    rec->cue_placement = choice::Position(balls->front());
    rec->stroke = stroke;
    return stroke;
  }
  choice::ChoiceOptions choice = c.options.choice;
  choice.rules = state.rules[state.shooter];
  return PlayerStroke(*c.options.players[state.shooter],
                      {c.table, c.params, *balls, constraints}, choice,
                      choice::SampleSeed(c.seed, static_cast<std::uint64_t>(n)), c.pool, balls,
                      rec);
}

// Shot n of the rack: decided, executed with the table's noise, judged (the rack's state
// advanced), the balls left as the rules leave them. False when the shooter had no stroke.
bool PlayShot(const RackContext& c, int n, rules::RackState* state,
              std::vector<table::SceneBall>* balls, ShotRecord* rec) {
  rec->number = n + 1;
  rec->player = state->shooter;
  rec->ball_in_hand = state->ball_in_hand;
  const rules::Constraints constraints = rules::NextConstraints(*state, *balls);
  const std::optional<physics::CueStroke> stroke =
      StrokeOf(c, n, *state, constraints, balls, rec);
  if (!stroke) return false;
  const choice::StrokeResult result = ExecuteWithNoise(
      c.table, c.params, *balls, *stroke, c.options.execution,
      choice::SampleSeed(c.seed + kExecutionStream, static_cast<std::uint64_t>(n)), c.motion);
  const rules::Shot shot = ShotOf(constraints, *rec, result);
  const rules::Judgement judgement = rules::Referee(c.table, shot, state);
  rec->first_contact = shot.first_contact;
  rec->potted = shot.potted;
  rec->foul = judgement.foul;
  rec->foul_reason = judgement.foul_reason;
  rec->called_potted = rec->ball >= 0 && judgement.legal() && CalledBallPotted(shot);
  *balls = result.rest;
  rules::PlaceRespotted(c.table, c.params.ball.radius, judgement.respots, kRespotStep,
                        kRespotClearance, balls);
  return true;
}

void Tally(const ShotRecord& rec, PlayerTally* tally) {
  if (rec.foul) {
    ++tally->fouls;
    ++tally->foul_reasons[rec.foul_reason];
  }
  if (rec.break_shot) return;
  tally->decisions_us.push_back(rec.decision_us);
  tally->safeties += rec.safety;
  if (rec.ball < 0) return;
  ++tally->attempts;
  tally->pots += rec.called_potted;
}

}  // namespace

MatchOptions OptionsOf(const MatchNames& names) {
  MatchOptions options;
  const std::optional<rules::Rules> game = rules::ParseRules(names.game);
  if (!game || *game == rules::Rules::kAny) {
    throw std::invalid_argument("game: unknown game '" + names.game + "' (nine-ball, eight-ball)");
  }
  options.game = *game;
  try {
    options.players = {players::MakePlayer(names.players[0]),
                       players::MakePlayer(names.players[1])};
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("players: ") + e.what());
  }
  try {
    options.execution = params::LoadNoise(names.noise);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("noise: ") + e.what());
  }
  options.choice.noise = options.execution;
  // The table plays the parameter set's own constants, and the players know them as they know
  // its noise: FastFiz's agents knew the physics they played on. Drawn within the set's
  // uncertainty (a real table nobody measured), they made ours doubt the shots this table gives
  // (100 nine-ball racks against easiest-looking: 181 safeties and 79 racks won, 130 and 86
  // with the constants known).
  options.choice.sample_constants = false;
  options.seed = names.seed;
  options.racks = names.racks;
  options.shot_limit = names.shot_limit;
  return options;
}

RackResult PlayRack(const table::TableGeometry& table, const physics::ModelParameters& params,
                    int rack, const MatchOptions& options, batch::ThreadPool& pool,
                    std::array<PlayerTally, 2>* tallies) {
  const RackContext c{table, params, options, pool, model_choice::TableMotion(params),
                      choice::SampleSeed(options.seed, static_cast<std::uint64_t>(rack))};
  RackResult result;
  result.rack = rack;
  result.breaker = rack % 2;
  std::vector<table::SceneBall> balls =
      table::Rack(RackKindOf(options.game), table, params.ball.radius, c.seed);
  rules::RackState state = rules::NewRack(options.game, result.breaker);
  result.reason = "shot limit";
  for (int n = 0; n < options.shot_limit && !state.over; ++n) {
    ShotRecord rec;
    if (!PlayShot(c, n, &state, &balls, &rec)) {
      result.reason = "no stroke: " + rec.status + ", " + rec.reason;
      break;
    }
    Tally(rec, &(*tallies)[rec.player]);
    result.shots.push_back(std::move(rec));
  }
  if (state.over) {
    result.winner = state.winner;
    result.reason = state.reason;
    result.break_and_run =
        state.winner == result.breaker &&
        std::all_of(result.shots.begin(), result.shots.end(),
                    [&](const ShotRecord& s) { return s.player == result.breaker; });
  }
  for (std::size_t i = 0; i < result.shots.size(); ++i) {
    if (result.shots[i].safety) {
      (*tallies)[result.shots[i].player].safeties_that_worked += SafetyWorked(result, i);
    }
  }
  return result;
}

MatchRecord PlayMatch(const table::TableGeometry& table, const physics::ModelParameters& params,
                      const MatchOptions& options, batch::ThreadPool& pool,
                      const std::function<void(const RackResult&)>& progress) {
  MatchRecord match;
  for (int p = 0; p < 2; ++p) match.players[p].name = options.players[p]->Name();
  for (int rack = 0; rack < options.racks; ++rack) {
    RackFigures figures;
    RackResult r = PlayRack(table, params, rack, options, pool, &figures.players);
    figures.winner = r.winner;
    figures.break_and_run = r.break_and_run;
    AddRack(figures, &match);
    if (progress) progress(r);
    match.racks.push_back(std::move(r));
  }
  return match;
}

bool SafetyWorked(const RackResult& rack, std::size_t i) {
  const int player = rack.shots[i].player;
  for (std::size_t j = i + 1; j < rack.shots.size(); ++j) {
    const ShotRecord& next = rack.shots[j];
    if (next.player == player) continue;
    return next.foul || next.ball < 0 || next.predicted <= kSafetyWorkedBelow;
  }
  return rack.winner == player;
}

double Quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
  return values[std::min(values.size() - 1, rank == 0 ? 0 : rank - 1)];
}

}  // namespace billiard::game
