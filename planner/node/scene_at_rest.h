// The balls of the latest table state as the scene a pot or a choice is planned in: each at rest
// where it was seen, the struck ball the scene's cue ball (id 0), and the table state's id of
// each of the scene's ids kept, so that the answer names the balls as the table state does.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "sim/table/scene.h"

namespace billiard::planner_node {

// Why `ball` is no start for a plan, "ball 3 is moving (0.4 m/s, more than 0.05 m/s)", when it is
// faster than `max_ball_speed` [m/s]; empty when it is at rest.
std::string Moving(const ball_state_t& ball, double max_ball_speed);

// The first ball of `state` that Moving names, empty when every ball is at rest.
std::string MovingBall(const table_state_t& state, double max_ball_speed);

// The balls of `state` at rest, sorted by id, so that the plan does not depend on the
// publisher's order: the one of `cue_track` id 0 and the others by `scene_id` (their message ids
// kept in `message_id`); nullopt and `moving` set when a ball moves faster than `max_ball_speed`
// [m/s].
std::optional<std::vector<table::SceneBall>> SceneAtRest(
    const table_state_t& state, double max_ball_speed, int32_t cue_track,
    const std::function<int(int32_t)>& scene_id, std::unordered_map<int, int32_t>* message_id,
    std::string* moving);

// SceneAtRest with `struck` the scene's cue ball (id 0) and the others by their ids (one that is
// 0 takes a free id): the scene a pot, a choice or a stroke to a point is played in.
std::optional<std::vector<table::SceneBall>> StruckScene(const table_state_t& latest, const ball_state_t& struck,
                                                         double max_ball_speed,
                                                         std::unordered_map<int, int32_t>* message_id,
                                                         std::string* moving);

}  // namespace billiard::planner_node
