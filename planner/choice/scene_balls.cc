#include "planner/choice/scene_balls.h"

#include <utility>

#include "sim/table/rack.h"

namespace billiard::choice {

const table::SceneBall* FindBall(const std::vector<table::SceneBall>& balls, int id) {
  for (const table::SceneBall& b : balls) {
    if (b.id == id) return &b;
  }
  return nullptr;
}

Eigen::Vector2d Position(const table::SceneBall& b) { return b.state.segment<2>(physics::kX); }

std::vector<table::SceneBall> WithCueBallAt(std::vector<table::SceneBall> balls,
                                            const Eigen::Vector2d& place) {
  return table::WithBallAt(std::move(balls), 0, place);
}

}  // namespace billiard::choice
