// The ball a request names among the balls of the table states: by its id, or by its class (the
// one the estimator is surest of). A request's struck ball and a pot's object ball are found so.
#pragma once

#include <cstdint>
#include <vector>

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"

namespace billiard::planner_node {

// A ball asked for by class (shot_request_t::BALL_BY_CLASS) must be of that class with at least
// this confidence: an even guess between two classes is no ball to strike.
inline constexpr float kMinClassConfidence = 0.5f;

// The ball `id` names among `balls`; with shot_request_t::BALL_BY_CLASS, the one of
// `ball_class` the estimator is surest of, at least `min_confidence`. Ties by id: the answer
// must not depend on the balls' order. nullptr when there is none.
const ball_state_t* Named(const std::vector<const ball_state_t*>& balls, int32_t id,
                          int8_t ball_class, float min_confidence = kMinClassConfidence);

// The balls of `table`, in its order, to look a ball up among.
std::vector<const ball_state_t*> BallsOf(const table_state_t& table);

}  // namespace billiard::planner_node
