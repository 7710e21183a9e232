#include "sim/table_sim_node/truth_frame.h"

#include <algorithm>

#include "sim/table_sim_node/session_balls.h"

namespace billiard::table_sim_node {

std::vector<TruthBall> AtRest(const std::vector<table::SceneBall>& balls) {
  std::vector<TruthBall> still;
  for (const table::SceneBall& b : balls) {
    physics::BallState rest = b.state;
    rest.tail<5>().setZero();
    still.push_back({b.id, [rest](double) { return rest; }});
  }
  return still;
}

std::vector<TruthBall> OnTable(const table::TableSimulation& sim, double t_strike, double now) {
  const double since = now - t_strike;
  std::vector<TruthBall> on_table;
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    if (sim.pocket(i) && since >= sim.segments(i).back().start_time()) continue;
    on_table.push_back({sim.id(i), [&sim, i, t_strike](double t) {
                          return sim.StateAt(i, std::min(t - t_strike, sim.time()));
                        }});
  }
  return on_table;
}

table_state_t TruthMessage(const std::vector<TruthBall>& balls, double t, std::int64_t utime) {
  table_state_t truth{};
  truth.utime = utime;
  for (const TruthBall& ball : balls) {
    const physics::BallState x = ball.state(t);
    ball_state_t b{};  // the truth has no covariance
    b.utime = utime;
    b.ball_id = ball.id;
    b.ball_class = TruthClass(ball.id);
    b.class_confidence = 1.0f;
    std::copy(x.data(), x.data() + 2, b.position);
    std::copy(x.data() + physics::kVx, x.data() + physics::kVx + 2, b.velocity);
    std::copy(x.data() + physics::kWx, x.data() + physics::kWx + 3, b.spin);
    truth.balls.push_back(b);
  }
  truth.num_balls = static_cast<std::int32_t>(truth.balls.size());
  return truth;
}

std::vector<render::RenderBall> RenderedBalls(const std::vector<TruthBall>& balls) {
  std::vector<render::RenderBall> shown;
  for (const TruthBall& ball : balls) {
    const auto& state = ball.state;
    shown.push_back({ball.id, render::PoolBallColour(ball.id),
                     [state](double time) { return Eigen::Vector2d(state(time).head<2>()); },
                     render::PoolBallStriped(ball.id)});
  }
  return shown;
}

}  // namespace billiard::table_sim_node
