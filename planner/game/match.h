// A match in simulation: two players (planner/players/), racks of nine-ball or eight-ball, the
// break alternating by rack, each rack played visit by visit and judged by the rules: a player
// shoots while the rules keep it at the table, and a foul, a miss or (eight-ball) a pot not as
// called hands the table to the other. The rack's state (whose turn, the fouls in a row, the
// groups; rules::RackState) is the rules'; a player is shown the table and the constraints of
// its shot (rules::NextConstraints) and decides, and under eight-ball its chosen pot's ball and
// pocket are its call.
//
// The break is the game's (MatchOptions::opening, else the optimised StoredBreak of
// break_search.h: the cue ball placed on the head string, struck within the robot's ranges),
// whoever breaks; the players decide every other shot. A scratch leaves the cue
// ball off the table and the next player places it (ball in hand anywhere). Push-outs are in
// the rules but no player declares one yet. A rack not over after shot_limit shots is
// undecided (won by neither).
//
// Deterministic: rack r is seeded SampleSeed(seed, r) (its layout, the players' samples of shot
// n from SampleSeed(rack seed, n), the table's noise from a stream of its own), and racks are
// played one after the other, each choice on `pool`'s threads: the same seed plays the same
// match whatever the thread count.
//
// Module: billiard::game.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/game/break_search.h"
#include "planner/game/table_shot.h"
#include "planner/players/player.h"
#include "sim/batch/thread_pool.h"
#include "sim/params/execution_noise.h"
#include "sim/physics/parameters.h"
#include "sim/rules/rules.h"
#include "sim/table/table_geometry.h"

namespace billiard::game {

// A safety worked when the opponent's next shot was no attempt above this probability.
inline constexpr double kSafetyWorkedBelow = 0.5;

struct MatchOptions {
  rules::Rules game = rules::Rules::kNineBall;  // kNineBall or kEightBall
  std::array<std::shared_ptr<const players::Player>, 2> players;
  // Both players' choice (its noise the one they assume); its rules are set shot by shot to the
  // shooter's, its seed to the shot's.
  choice::ChoiceOptions choice;
  params::ExecutionNoise execution = params::LoadNoise(params::kDefaultNoise);  // the table's
  std::uint64_t seed = 1;
  int racks = 1;
  int shot_limit = 200;  // per rack
  std::optional<Break> opening;  // the break; none: the game's StoredBreak
};

// A match by name, as `billiard match`'s options and the Python module's arguments give it.
struct MatchNames {
  std::string game;                    // "nine-ball" or "eight-ball"
  std::array<std::string, 2> players;  // planner/players/players.h's names
  std::string noise;                   // params::LoadNoise's name or file
  std::uint64_t seed = 1;
  int racks = 1;
  int shot_limit = 200;
};

// The options `names` names, the table's noise also the one the players assume and its constants
// known to them exactly (ChoiceOptions::sample_constants off); throws
// std::invalid_argument beginning with the field at fault ("game: ", "players: ", "noise: ").
MatchOptions OptionsOf(const MatchNames& names);

// What a player did over the match.
struct PlayerTally {
  std::string name;
  int racks_won = 0;
  int break_and_runs = 0;  // racks it broke and won with the other player never at the table
  int attempts = 0;        // shots calling a pot (the break is none)
  int pots = 0;            // of those, the called ball potted legally in the called pocket
  int safeties = 0;        // defensive strokes played (planner/choice/safety.h)
  // Of those, the ones after which the opponent's next shot fouled or had no attempt above
  // kSafetyWorkedBelow (its own reported probability); a rack won before the opponent shot
  // again counts too.
  int safeties_that_worked = 0;
  int fouls = 0;
  std::map<std::string, int> foul_reasons;  // the fouls by the rules' reason
  std::vector<double> decisions_us;  // every decision's time, in the order made
};

struct RackResult {
  int rack = 0;
  int breaker = 0;
  int winner = -1;  // -1: undecided (the shot limit)
  std::string reason;  // why it ended (rules::RackState::reason), "shot limit" when undecided
  bool break_and_run = false;
  std::vector<ShotRecord> shots;
};

struct MatchRecord {
  std::vector<RackResult> racks;
  std::array<PlayerTally, 2> players;
  int undecided = 0;
};

// Rack `rack` of `options` (broken by player rack % 2), its shots tallied into `tallies`.
RackResult PlayRack(const table::TableGeometry& table, const physics::ModelParameters& params,
                    int rack, const MatchOptions& options, batch::ThreadPool& pool,
                    std::array<PlayerTally, 2>* tallies);

// options.racks racks, `progress` told of each as it ends.
MatchRecord PlayMatch(const table::TableGeometry& table, const physics::ModelParameters& params,
                      const MatchOptions& options, batch::ThreadPool& pool,
                      const std::function<void(const RackResult&)>& progress = {});

// Whether shot i of `rack`, a safety, worked: the opponent's first shot after it fouled or had
// no attempt above kSafetyWorkedBelow (no call, or a called pot of that probability or less);
// with no shot of the opponent after it, whether its player won the rack.
bool SafetyWorked(const RackResult& rack, std::size_t i);

// The value at fraction q (0 to 1) of `values` by nearest rank; 0 when empty.
double Quantile(std::vector<double> values, double q);

}  // namespace billiard::game
