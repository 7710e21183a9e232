// table_state_t: the estimator's and the simulator's output, which the planner decodes.
#include "fuzz/support.h"

namespace billiard::fuzz {
namespace {

ball_state_t Ball(std::int32_t id, double x, double y, double speed) {
  ball_state_t b{};
  b.utime = 1000;
  b.ball_id = id;
  b.position[0] = x;
  b.position[1] = y;
  b.velocity[0] = speed;
  b.velocity[1] = -0.5 * speed;
  b.spin[1] = speed / 0.028575;
  b.spin[2] = 3.0;
  for (int i = 0; i < 7; ++i) b.covariance[8 * i] = 1e-6;
  return b;
}

table_state_t Table(std::vector<ball_state_t> balls) {
  table_state_t m{};
  m.utime = 2000;
  m.num_balls = static_cast<std::int32_t>(balls.size());
  m.balls = std::move(balls);
  return m;
}

}  // namespace

std::vector<Bytes> Seeds() {
  return {Encode(Table({})), Encode(Table({Ball(0, 0.5, 0.5, 0.0)})),
          Encode(Table({Ball(0, 0.1, 0.2, 1.5), Ball(3, 1.2, 0.6, 0.0), Ball(15, 2.0, 1.0, 0.3)}))};
}

}  // namespace billiard::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  billiard::table_state_t m;
  billiard::fuzz::DecodeAndCheck(data, size, m);
  return 0;
}
