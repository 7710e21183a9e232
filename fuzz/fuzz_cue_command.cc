// cue_command_t: the planner's answer, with its predicted path and a refusal's reason.
#include "fuzz/support.h"

namespace billiard::fuzz {

std::vector<Bytes> Seeds() {
  cue_command_t planned{};
  planned.utime = 9000;
  planned.request_id = 4;
  planned.ball_id = 0;
  planned.cue_speed = 1.5;
  planned.heading = 0.3;
  planned.tip_height = 0.01;
  planned.v0[0] = 1.2;
  planned.w0[1] = 40.0;
  planned.start[0] = 0.5;
  planned.path = {{0.5, 0.5}, {0.9, 0.6}, {1.4, 0.75}};
  planned.num_path_points = 3;
  planned.predicted_final[0] = 1.5;
  planned.predicted_final[1] = 0.8;
  planned.refined_miss_m = 1e-6;
  planned.solve_us = 1200.0;
  planned.iterations = 5;
  planned.status = cue_command_t::STATUS_OK;

  cue_command_t refused{};
  refused.utime = 9100;
  refused.request_id = 5;
  refused.status = cue_command_t::STATUS_OFF_TABLE;
  refused.reason = "target (5, 0.5) is off the table";

  cue_command_t busy = refused;
  busy.status = cue_command_t::STATUS_BUSY;
  busy.reason = "queue full";

  // A pot: the cue ball's and the object ball's paths, the margin and the speed window.
  cue_command_t pot = planned;
  pot.mode = shot_request_t::MODE_POT;
  pot.object_ball_id = 3;
  pot.pocket = "lower_left";
  pot.kind = shot_request_t::KIND_BANK;
  pot.margin_deg[0] = 0.3;
  pot.margin_deg[1] = 0.5;
  pot.speed_window[0] = 1.1;
  pot.speed_window[1] = 2.4;
  pot.cue_rest[0] = 1.5;
  pot.cue_rest[1] = 0.8;
  pot.ball_paths = {{0, 3, planned.path}, {3, 2, {{1.0, 0.5}, {0.03, 0.03}}}};
  pot.num_ball_paths = 2;

  cue_command_t blocked = refused;
  blocked.mode = shot_request_t::MODE_POT;
  blocked.object_ball_id = 3;
  blocked.pocket = "lower_left";
  blocked.status = cue_command_t::STATUS_BLOCKED;
  blocked.reason = "ball 5 blocks the direct line; no bank, kick or curve pots it";
  return {Encode(planned), Encode(refused), Encode(busy), Encode(pot), Encode(blocked)};
}

}  // namespace billiard::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  billiard::cue_command_t m;
  billiard::fuzz::DecodeAndCheck(data, size, m);
  return 0;
}
