// A player: who decides the shot. Given the table, the balls at rest and what the rules allow
// this shot (rules::Constraints: the cue ball in hand or not), it answers with the stroke to
// play and, in hand, where the cue ball goes first (choice::ChoiceResult::stroke(),
// cue_placement), with the call and the estimates behind it. It only decides: the table plays
// the stroke and the rules (sim/rules/) judge what it did.
//
// The players are a file each (ours_player.h, with or without the lookahead;
// easiest_looking_player.h), found by name in players.h.
//
// Module: billiard::players.
#pragma once

#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/choice/choice_result.h"
#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/rules/ruleset.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::players {

// What a player is shown before its shot.
struct Turn {
  const table::TableGeometry& table;
  const physics::ModelParameters& params;
  // Id 0 the cue ball (which may be absent when in hand); every ball at rest.
  const std::vector<table::SceneBall>& balls;
  rules::Constraints constraints;  // the cue ball in hand or not, the legal first contacts
  // The rack is played alone (billiard play, the loop's game without --players): a miss or a
  // foul leaves this player at the table again. A safety is worth what it leaves an opponent, so
  // a player alone weighs none: its own next shot would be the one left hard (two selves
  // exchanging safeties to the shot limit, rack seed 15 of the 20-rack loop, 34 safeties).
  bool alone = false;
};

class Player {
 public:
  virtual ~Player() = default;

  // "ours", "no-lookahead", "easiest-looking".
  virtual const char* Name() const = 0;

  // The decision of `turn`, with `options` (the rules played under, whose legal targets are
  // the turn's and whose end of the rack the lookahead sees; the noise assumed; the seed of its
  // samples) on `pool`'s threads. Deterministic in its arguments.
  virtual choice::ChoiceResult Decide(const Turn& turn, const choice::ChoiceOptions& options,
                                      batch::ThreadPool& pool) const = 0;
};

}  // namespace billiard::players
