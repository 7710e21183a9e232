#include "sim/table/testing/breaks.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include "sim/physics/cue_strike.h"

namespace billiard::table::testing {

std::vector<SceneBall> SeededBreak(const TableGeometry& table, const physics::ModelParameters& p,
                                   std::uint64_t seed, const BreakOptions& options) {
  std::vector<SceneBall> balls = Rack(options.rack, table, p.ball.radius, seed);
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ull);
  const auto symmetric = [&](double half_width) {
    return half_width * (2.0 * static_cast<double>(rng() >> 11) * 0x1.0p-53 - 1.0);
  };
  SceneBall* cue = nullptr;
  const SceneBall* apex = nullptr;
  for (SceneBall& b : balls) {
    if (b.id == 0) cue = &b;
  }
  if (cue == nullptr) throw std::invalid_argument("the rack has no cue ball");
  // The apex: the object ball nearest the cue ball.
  double nearest = INFINITY;
  for (const SceneBall& b : balls) {
    const double d = (b.state.head<2>() - cue->state.head<2>()).norm();
    if (b.id != 0 && d < nearest) {
      nearest = d;
      apex = &b;
    }
  }
  if (apex == nullptr) throw std::invalid_argument("the rack has no object ball");
  const Eigen::Vector2d line = apex->state.head<2>() - cue->state.head<2>();
  physics::CueStroke stroke;
  stroke.heading = std::atan2(line.y(), line.x()) + symmetric(options.max_aim_error);
  stroke.tip_side = symmetric(options.max_tip_offset) * p.ball.radius;
  stroke.tip_height = symmetric(options.max_tip_offset) * p.ball.radius;
  // The launch speed is proportional to the cue speed (TP A.30, with the squirt of TP A.31):
  // strike once at 1 m/s, then at the cue speed that launches the ball at options.speed.
  stroke.speed = 1.0;
  const double per_cue_speed =
      physics::StrikeBall(stroke, cue->state.head<2>(), p).segment<2>(physics::kVx).norm();
  stroke.speed = options.speed / per_cue_speed;
  *cue = table::Struck(cue->id, stroke, cue->state.head<2>(), p);
  return balls;
}

}  // namespace billiard::table::testing
