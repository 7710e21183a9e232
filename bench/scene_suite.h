// The fixed, seeded scenes the speed-against-error benchmark runs every method on.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim/physics/ball_state.h"
#include "sim/physics/parameters.h"

namespace billiard::bench {

struct Scene {
  std::string name;   // "fig6", "random017", "hard-backspin-reversal", ...
  std::string group;  // "figure", "random" or "hard"
  physics::BallState initial;
  double t_end = 8.0;
};

// The five Figs. 6-10 states, `random_shots` cue shots drawn with `seed`, and the hard cases of
// the physics core. Random shots: ball speed uniform in [0.2, 4] m/s, heading uniform, a level
// cue; a quarter natural roll, a quarter with the tip on the vertical centre line (stun, follow,
// draw), half with the tip uniform over the disc the cue allows (p.cue.max_tip_offset r); v0 and
// w0 follow from the cue strike model.
std::vector<Scene> SceneSuite(const physics::ModelParameters& p, int random_shots,
                              std::uint32_t seed);

// The scenes of one group ("figure", "random" or "hard"), in suite order.
std::vector<Scene> ScenesOfGroup(const std::vector<Scene>& scenes, const std::string& group);

}  // namespace billiard::bench
