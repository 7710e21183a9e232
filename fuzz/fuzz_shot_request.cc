// shot_request_t: what the planner is asked to do.
#include "fuzz/support.h"

namespace billiard::fuzz {

std::vector<Bytes> Seeds() {
  std::vector<Bytes> seeds;
  for (std::int8_t spin = shot_request_t::SPIN_NATURAL; spin <= shot_request_t::SPIN_SLIDE;
       ++spin) {
    shot_request_t m{};
    m.utime = 5000;
    m.request_id = 7 + spin;
    m.ball_id = spin;
    m.target[0] = 1.5;
    m.target[1] = 0.8;
    m.final_speed = 0.1 * spin;
    m.spin = spin;
    m.slide_length = spin == shot_request_t::SPIN_SLIDE ? 0.3 : 0.0;
    m.side_spin = spin % 2 == 0 ? 0.0 : -20.0;
    seeds.push_back(Encode(m));
  }
  return seeds;
}

}  // namespace billiard::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  billiard::shot_request_t m;
  billiard::fuzz::DecodeAndCheck(data, size, m);
  return 0;
}
