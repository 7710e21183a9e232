// What a table simulator session measured, as the one JSON object its command prints
// (session.h's RunSessionCommand): the shots and their misses, the node's counters, and what a
// game (GameSummary) or a whole-table session (SceneSummary) adds.
//
// Module: billiard::table_sim_node.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lcmtypes/billiard/node_status_t.hpp"
#include "sim/table_sim_node/table_sim_node.h"

namespace billiard::table_sim_node {

// What the session measured: the shots, the misses' median, max, mean and spread, the node's
// counters and the wall time.
nlohmann::json SessionSummary(const std::vector<ShotResult>& shots, const node_status_t& health,
                              double wall_s);

// What a game adds (the summary's "game"): each rack's shots (the call, what dropped, the foul,
// the decision time and the estimator's error on the table it was made from) and totals, and
// "summary": racks cleared, run-outs (cleared in one visit), pots per attempt, fouls, balls per
// visit, the median and largest decision time, the estimator's median RMS and largest position
// error at the decisions and the balls it misidentified there. A match's (two `players` by name)
// also says who played each shot and whether it was a safety, each rack's breaker, winner and
// why it ended, and "players": each player's racks won, win rate with its Wilson 95 % interval
// (sim/rules/match_standing.h), break-and-runs, pots, attempts, safeties and fouls, as `billiard match`
// gives them; a player against itself named "ours (A)" and "ours (B)".
nlohmann::json GameSummary(const std::vector<GameResult>& games, const std::string& kind,
                           std::vector<std::string> players = {});

// What a whole-table session adds (the summary's "scene"): the events, where every ball ended
// (and the pocket it dropped into), how the estimator tracked each ball (RMS and largest error,
// frames without a track, swaps of tracks between balls), and with pots, "pots": each one's ball
// and pocket, the planner's status, reason, kind, margin and speed window, whether it dropped
// (and where), a scratch, the cue ball's first contact, and its rest against the plan's.
nlohmann::json SceneSummary(const SceneResult& scene, const std::string& name);

// The noise the robot drew (the summary's "drawn_noise"): {"strokes", "speed_fraction",
// "heading_deg", "tip_mm"}, in the units of identify-noise's "learned_noise".
nlohmann::json DrawnNoiseJson(const DrawnNoise& drawn);

}  // namespace billiard::table_sim_node
