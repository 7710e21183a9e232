#include "bench/scene_suite.h"

#include <cmath>
#include <cstdio>
#include <random>

#include "sim/physics/cue_strike.h"

namespace billiard::bench {

std::vector<Scene> SceneSuite(const physics::ModelParameters& p, int random_shots,
                              std::uint32_t seed) {
  std::vector<Scene> scenes;
  const double figure_spins[5][3] = {
      {-50, 0, 0}, {-50, 5, 0}, {150, 5, 0}, {-50, -3.5, -150}, {150, 0, -150}};
  for (int i = 0; i < 5; ++i) {
    const double* w = figure_spins[i];
    scenes.push_back({"fig" + std::to_string(i + 6), "figure",
                      physics::MakeBallState(0, 0, 0, 1, w[0], w[1], w[2]), 8.0});
  }

  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < random_shots; ++i) {
    const double speed = 0.2 + 3.8 * unit(rng), heading = 2 * M_PI * unit(rng);
    const double offset = p.cue.max_tip_offset * p.ball.radius * std::sqrt(unit(rng));
    const double angle = 2 * M_PI * unit(rng);
    // A quarter are natural-roll shots, a quarter stun, follow or draw shots in the vertical
    // plane, and half take the tip anywhere the cue allows (side spin).
    physics::CueStroke stroke{1.0, heading, offset * std::cos(angle), offset * std::sin(angle),
                              0.0};
    if (i % 4 == 0) {
      stroke.tip_side = 0.0, stroke.tip_height = 0.4 * p.ball.radius;
    } else if (i % 4 == 2) {
      stroke.tip_side = 0.0;
    }
    stroke.speed = speed / physics::StrikeBall(stroke, {0, 0}, p).segment<2>(physics::kVx).norm();
    char name[32];
    std::snprintf(name, sizeof name, "random%03d", i);
    scenes.push_back({name, "random", physics::StrikeBall(stroke, {0, 0}, p), 8.0});
  }

  const std::pair<const char*, physics::BallState> hard[] = {
      {"hard-sidespin-plus-1000", physics::MakeBallState(0, 0, 0, 1, -50, 0, 1000)},
      {"hard-sidespin-minus-1000", physics::MakeBallState(0, 0, 0, 1, -50, 0, -1000)},
      {"hard-at-rest-only-sidespin", physics::MakeBallState(0, 0, 0, 0, 0, 0, 80)},
      {"hard-backspin-reversal", physics::MakeBallState(0, 0, 0, 1, 150, 0, 0)},
      {"hard-zero-velocity-topspin", physics::MakeBallState(0, 0, 0, 0, -60, 20, 0)},
      {"hard-zero-velocity-spin-and-sidespin", physics::MakeBallState(0, 0, 0, 0, 40, 0, -300)}};
  for (const auto& [name, state] : hard) scenes.push_back({name, "hard", state, 8.0});
  scenes.push_back({"hard-sixty-second-horizon", "hard",
                    physics::MakeBallState(0, 0, 0, 1, -50, -3.5, -150), 60.0});
  return scenes;
}

std::vector<Scene> ScenesOfGroup(const std::vector<Scene>& scenes, const std::string& group) {
  std::vector<Scene> of_group;
  for (const Scene& s : scenes) {
    if (s.group == group) of_group.push_back(s);
  }
  return of_group;
}

}  // namespace billiard::bench
