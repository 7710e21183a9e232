// A rack played (game.h) as JSON, the one writer of `billiard play --json` and of the Python
// module's billiard.play, so that the two say the same: each shot (the call, the stroke with its
// cue's clearance, the outcome, whether it was a safety), the summary and the balls left. The
// stroke's and the clearance's objects are the ones every planning command writes under "cue".
//
// Module: billiard::game.
#pragma once

#include <nlohmann/json.hpp>

#include "planner/game/game.h"
#include "planner/game/table_shot.h"
#include "sim/cue/clearance.h"
#include "sim/physics/cue_strike.h"

namespace billiard::game {

// {"speed" [m/s], "heading" [rad], "tip_side", "tip_height" [ball radii], "elevation" [rad]}.
nlohmann::json CueStrokeJson(const physics::CueStroke& stroke);

// {"clears", "nearest" (what is nearest the cue), "ball" (its id, when a ball is), "distance"
// [m], null when nothing is near: an empty table and no body; JSON has no infinity; "along", where
// on the cue it comes nearest [m from the tip], when something is}.
nlohmann::json ClearanceJson(const cue::CueClearance& clearance);

// One shot: its number and visit, the break and ball in hand, the cue ball's placement ([x, y]
// or null), the choice's status and reason, the call (ball, pocket, kind, predicted, likely),
// "safety", "cue" (CueStrokeJson with "clearance" where the robot's cue was checked; null when
// nothing was struck), the outcome (first contact, balls potted, the call potted, the foul and
// why) and the decision's wall time [us].
nlohmann::json ShotJson(const ShotRecord& shot);

// {"shots": [ShotJson...], "summary": {...}, "balls_left": [ids]}.
nlohmann::json GameJson(const GameRecord& game);

}  // namespace billiard::game
