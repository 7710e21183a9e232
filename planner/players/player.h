// A player: who decides the shot. Given the table, the balls at rest and what the rules allow
// this shot (rules::Constraints: the cue ball in hand or not), it answers with the stroke to
// play and, in hand, where the cue ball goes first (choice::ChoiceResult::stroke(),
// cue_placement), with the call and the estimates behind it. It only decides: the table plays
// the stroke and the rules (sim/rules/) judge what it did.
//
// The players are a file each (ours_player.h, no_lookahead_player.h,
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

class Player {
 public:
  virtual ~Player() = default;

  // "ours", "no-lookahead", "easiest-looking".
  virtual const char* Name() const = 0;

  // The decision on `balls` (id 0 the cue ball, which may be absent in hand; every ball at
  // rest) under `constraints`, with `options` (the rules played under, whose legal targets are
  // constraints.legal_targets and whose end of the rack the lookahead sees; the noise assumed;
  // the seed of its samples) on `pool`'s threads. Deterministic in its arguments.
  virtual choice::ChoiceResult Decide(const table::TableGeometry& table,
                                      const physics::ModelParameters& params,
                                      const std::vector<table::SceneBall>& balls,
                                      const rules::Constraints& constraints,
                                      const choice::ChoiceOptions& options,
                                      batch::ThreadPool& pool) const = 0;
};

}  // namespace billiard::players
