#include "sim/shot_fit/synthetic_shots.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

namespace billiard::shot_fit {

TrackedShot SimulateTrackedShot(const table::TableGeometry& table,
                                const physics::ModelParameters& params,
                                const std::vector<Eigen::Vector2d>& starts, std::size_t cue,
                                const Strike& strike, double duration, double period, double noise,
                                double thinning, std::uint64_t seed) {
  if (cue >= starts.size()) throw std::invalid_argument("SimulateTrackedShot: no such cue ball");
  TrackedShot shot;
  shot.cue = cue;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    TrackedBall b;
    b.name = std::to_string(i + 1);
    b.t = {0.0};
    b.position = {starts[i]};
    shot.balls.push_back(b);
  }
  const ShotModel model(table, params, shot);
  const table::TableSimulation sim = model.Run(strike, duration);
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  const int samples = static_cast<int>(std::floor(duration / period + 1e-9)) + 1;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    TrackedBall& b = shot.balls[i];
    b.t.clear();
    b.position.clear();
    Eigen::Vector2d last_true = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    for (int k = 0; k < samples; ++k) {
      const double t = k * period;
      const double tau = std::clamp(t - strike.time, 0.0, sim.time());
      const Eigen::Vector2d p = sim.StateAt(i, tau).segment<2>(physics::kX);
      const Eigen::Vector2d seen = p + Eigen::Vector2d(gauss(random), gauss(random));
      const bool keep = k == 0 || k == samples - 1 || (p - last_true).norm() >= thinning;
      if (!keep) continue;
      b.t.push_back(t);
      b.position.push_back(seen);
      last_true = p;
    }
  }
  return shot;
}

std::vector<SyntheticScene> SyntheticScenes(const table::TableGeometry& table, double ball_radius,
                                            int count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r = ball_radius;
  std::vector<SyntheticScene> scenes;
  while (static_cast<int>(scenes.size()) < count) {
    SyntheticScene scene;
    while (scene.starts.size() < 3) {
      const Eigen::Vector2d q(2 * r + unit(random) * (table.length - 4 * r),
                              2 * r + unit(random) * (table.width - 4 * r));
      bool clear = true;
      for (const Eigen::Vector2d& o : scene.starts) clear = clear && (q - o).norm() > 3 * r;
      if (clear) scene.starts.push_back(q);
    }
    Strike& s = scene.strike;
    s.stroke.speed = 2.0 + 2.0 * unit(random);
    s.stroke.heading = 2 * M_PI * unit(random);
    s.stroke.tip_side = (unit(random) - 0.5) * 0.8 * r;
    s.stroke.tip_height = (unit(random) - 0.5) * 0.8 * r;
    s.time = kSyntheticPeriod * unit(random);
    scenes.push_back(std::move(scene));
  }
  return scenes;
}

std::vector<SyntheticScene> LoopScenes(const table::TableGeometry& table, double ball_radius,
                                       int count, std::uint64_t seed, bool natural_only) {
  // The spin styles' tip heights [r]: R w / v = 5/2 h / r at the launch (cue_strike.h).
  constexpr double kStyleHeights[] = {0.4, 0.0, 0.2, -0.4};
  constexpr double kSlowest = 0.25, kFastest = 0.6;  // the loop's cue speeds [m/s]
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<SyntheticScene> scenes(static_cast<std::size_t>(count));
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const Eigen::Vector2d start((1.0 + unit(random)) * table.length / 3.0,
                                (1.0 + unit(random)) * table.width / 3.0);
    scenes[k].starts = {start};
    Strike& s = scenes[k].strike;
    s.stroke.speed = kSlowest + (kFastest - kSlowest) * unit(random);
    s.stroke.heading = 2 * M_PI * unit(random);
    s.stroke.tip_height = (natural_only ? kStyleHeights[0] : kStyleHeights[k % 4]) * ball_radius;
    s.time = kSyntheticPeriod * unit(random);
  }
  return scenes;
}

std::vector<TrackedShot> SyntheticShots(const table::TableGeometry& table,
                                        const physics::ModelParameters& params, int count,
                                        std::uint64_t seed) {
  constexpr double kDuration = 8.0, kNoise = 0.001, kThinning = 0.002;
  std::vector<TrackedShot> shots;
  for (const SyntheticScene& scene : SyntheticScenes(table, params.ball.radius, count, seed)) {
    shots.push_back(SimulateTrackedShot(table, params, scene.starts, 0, scene.strike, kDuration,
                                        kSyntheticPeriod, kNoise, kThinning, seed + shots.size()));
    shots.back().id = std::to_string(shots.size());
  }
  return shots;
}

}  // namespace billiard::shot_fit
