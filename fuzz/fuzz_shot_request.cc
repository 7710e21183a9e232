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
  // A pot for each kind, by id and by class, with a cue-ball target and without.
  for (std::int8_t kind = shot_request_t::KIND_ANY; kind <= shot_request_t::KIND_CURVE; ++kind) {
    shot_request_t m{};
    m.utime = 6000;
    m.request_id = 20 + kind;
    m.ball_id = kind % 2 ? 0 : shot_request_t::BALL_BY_CLASS;
    m.ball_class = ball_state_t::CLASS_CUE;
    m.mode = shot_request_t::MODE_POT;
    m.object_ball_id = kind % 2 ? 3 : shot_request_t::BALL_BY_CLASS;
    m.object_ball_class = 9;
    m.pocket = kind % 2 ? "lower_left" : "upper_middle";
    m.kind = kind;
    m.has_cue_target = kind % 2;
    m.cue_target[0] = 1.0;
    m.cue_target[1] = 0.5;
    m.cue_radius = 0.1 * kind;
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
