#include "planner/node/named_ball.h"

#include "lcmtypes/billiard/shot_request_t.hpp"

namespace billiard::planner_node {

const ball_state_t* Named(const std::vector<const ball_state_t*>& balls, int32_t id,
                          int8_t ball_class, float min_confidence) {
  const ball_state_t* surest = nullptr;
  for (const ball_state_t* ball : balls) {
    if (id != shot_request_t::BALL_BY_CLASS) {
      if (ball->ball_id == id) return ball;
      continue;
    }
    if (ball->ball_class != ball_class || ball->class_confidence < min_confidence) continue;
    if (surest == nullptr || ball->class_confidence > surest->class_confidence ||
        (ball->class_confidence == surest->class_confidence && ball->ball_id < surest->ball_id)) {
      surest = ball;
    }
  }
  return surest;
}

std::vector<const ball_state_t*> BallsOf(const table_state_t& table) {
  std::vector<const ball_state_t*> balls;
  for (const ball_state_t& b : table.balls) balls.push_back(&b);
  return balls;
}

}  // namespace billiard::planner_node
