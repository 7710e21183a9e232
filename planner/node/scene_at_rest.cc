#include "planner/node/scene_at_rest.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sim/physics/ball_state.h"

namespace billiard::planner_node {

std::optional<std::vector<table::SceneBall>> SceneAtRest(
    const table_state_t& state, double max_ball_speed, int32_t cue_track,
    const std::function<int(int32_t)>& scene_id, std::unordered_map<int, int32_t>* message_id,
    std::string* moving) {
  std::vector<table::SceneBall> balls;
  for (const ball_state_t& b : state.balls) {
    const double speed = std::hypot(b.velocity[0], b.velocity[1]);
    if (speed > max_ball_speed) {
      std::ostringstream reason;
      reason << "ball " << b.ball_id << " is moving (" << speed << " m/s, more than "
             << max_ball_speed << " m/s)";
      *moving = reason.str();
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

}  // namespace billiard::planner_node
