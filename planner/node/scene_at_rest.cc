#include "planner/node/scene_at_rest.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "sim/physics/ball_state.h"

namespace billiard::planner_node {

std::string Moving(const ball_state_t& ball, double max_ball_speed) {
  const double speed = std::hypot(ball.velocity[0], ball.velocity[1]);
  if (speed <= max_ball_speed) return "";
  std::ostringstream reason;
  reason << "ball " << ball.ball_id << " is moving (" << speed << " m/s, more than "
         << max_ball_speed << " m/s)";
  return reason.str();
}

std::string MovingBall(const table_state_t& state, double max_ball_speed) {
  for (const ball_state_t& b : state.balls) {
    if (std::string why = Moving(b, max_ball_speed); !why.empty()) return why;
  }
  return "";
}

std::optional<std::vector<table::SceneBall>> SceneAtRest(
    const table_state_t& state, double max_ball_speed, int32_t cue_track,
    const std::function<int(int32_t)>& scene_id, std::unordered_map<int, int32_t>* message_id,
    std::string* moving) {
  std::vector<table::SceneBall> balls;
  for (const ball_state_t& b : state.balls) {
    if (std::string why = Moving(b, max_ball_speed); !why.empty()) {
      *moving = std::move(why);
      return std::nullopt;
    }
    const int id = b.ball_id == cue_track ? 0 : scene_id(b.ball_id);
    (*message_id)[id] = b.ball_id;
    balls.push_back({id, physics::MakeBallState(b.position[0], b.position[1], 0, 0, 0, 0, 0)});
  }
  // By id, so that the plan does not depend on the publisher's order.
  std::sort(balls.begin(), balls.end(),
            [](const table::SceneBall& a, const table::SceneBall& b) { return a.id < b.id; });
  return balls;
}

std::optional<std::vector<table::SceneBall>> StruckScene(const table_state_t& latest, const ball_state_t& struck,
                                                         double max_ball_speed,
                                                         std::unordered_map<int, int32_t>* message_id,
                                                         std::string* moving) {
  int32_t free_id = 1;
  for (const ball_state_t& b : latest.balls) free_id = std::max(free_id, b.ball_id + 1);
  return SceneAtRest(
      latest, max_ball_speed, struck.ball_id, [&](int32_t id) { return id == 0 ? free_id : id; }, message_id,
      moving);
}

}  // namespace billiard::planner_node
