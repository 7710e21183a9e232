// Simulated shots with ground truth for the estimator's tests and benchmark: balls at rest,
// some struck, and the comparison of tracks with the truth (accuracy, identities kept). A testing
// library (estimator_testing): it includes the estimator, the physics and the parameter sets; the
// benchmarks and the tests use it, no production code does.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <vector>

#include "estimator/ball_tracker.h"
#include "sim/params/parameter_sets.h"
#include "sim/physics/simulator.h"

namespace billiard::estimator::shots {

inline const physics::ModelParameters& Pool() {
  static const physics::ModelParameters p = params::LoadParameters("pool");
  return p;
}

// Balls on the table, some struck at t_strike: position at any time from the 5-DOF simulation.
struct Scene {
  std::vector<Eigen::Vector2d> rest;
  std::vector<std::shared_ptr<const physics::Trajectory>> motion;  // null: stays at rest
  double t_strike = 0.2;
  std::vector<std::vector<double>> phase_changes;  // per ball: strike, end of sliding, stop [s]

  Eigen::Vector2d At(std::size_t i, double t) const {
    if (!motion[i] || t < t_strike) return rest[i];
    return motion[i]->At(t - t_strike).head<2>();
  }
  Eigen::Vector2d VelocityAt(std::size_t i, double t) const {
    if (!motion[i] || t < t_strike) return Eigen::Vector2d::Zero();
    return motion[i]->At(t - t_strike).segment<2>(physics::kVx);
  }
};

// `balls` balls, `struck` of them launched with a random cue-like state (0.5-3 m/s, spin across
// the line from draw to follow, side spin up to 30 rad/s): the struck ones first, kept on the
// table and clear of each other, then the resting ones placed clear of every path.
inline Scene RandomScene(int balls, int struck, unsigned seed, double duration) {
  const physics::ModelParameters& p = Pool();
  const double r = p.ball.radius, clearance = 3 * r;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto random_point = [&] {
    return Eigen::Vector2d(0.15 + 2.24 * u(rng), 0.15 + 0.97 * u(rng));
  };
  const auto on_table = [&](const Eigen::Vector2d& x) {
    return x.x() > r && x.x() < 2.54 - r && x.y() > r && x.y() < 1.27 - r;
  };
  Scene s;
  std::vector<std::vector<Eigen::Vector2d>> paths;  // sampled every 5 ms
  while (static_cast<int>(paths.size()) < struck) {
    const Eigen::Vector2d start = random_point();
    const double speed = 0.5 + 2.5 * u(rng), heading = 2 * M_PI * u(rng);
    const double k = -1.0 + 2.0 * u(rng), wz = 60.0 * (u(rng) - 0.5);
    const Eigen::Vector2d e(std::cos(heading), std::sin(heading));
    const physics::BallState launch =
        physics::MakeBallState(start.x(), start.y(), speed * e.x(), speed * e.y(),
                               -k * speed / r * e.y(), k * speed / r * e.x(), wz);
    const auto trajectory = physics::Simulate(p, launch, duration).trajectory;
    std::vector<Eigen::Vector2d> path;
    bool clear = true;
    for (double t = 0.0; t <= duration && clear; t += 0.005) {
      path.push_back(trajectory->At(t).head<2>());
      clear = on_table(path.back());
      for (const auto& other : paths) {
        clear = clear && (path.back() - other[path.size() - 1]).norm() > clearance;
      }
    }
    if (!clear) continue;
    paths.push_back(path);
    s.rest.push_back(start);
    s.motion.push_back(trajectory);
    std::vector<double> changes = {s.t_strike};
    bool sliding = true, moving = true;
    for (double t = 0.0; t <= duration; t += 0.001) {
      const physics::BallState x = trajectory->At(t);
      const double slip = physics::ClothSlip(x, r).norm();
      if (sliding && slip < 0.01) changes.push_back(s.t_strike + t);
      if (moving && x.segment<2>(physics::kVx).norm() < 1e-3) changes.push_back(s.t_strike + t);
      sliding = sliding && slip >= 0.01;
      moving = moving && x.segment<2>(physics::kVx).norm() >= 1e-3;
    }
    s.phase_changes.push_back(changes);
  }
  while (static_cast<int>(s.rest.size()) < balls) {
    const Eigen::Vector2d x = random_point();
    bool clear = true;
    for (const auto& y : s.rest) clear = clear && (x - y).norm() > 4 * r;
    for (const auto& path : paths) {
      for (const auto& y : path) clear = clear && (x - y).norm() > clearance;
    }
    if (!clear) continue;
    s.rest.push_back(x);
    s.motion.push_back(nullptr);
    s.phase_changes.emplace_back();
  }
  return s;
}

// Root mean square of errors (0 for none).
inline double Rmse(const std::vector<double>& errors) {
  double sum = 0.0;
  for (double x : errors) sum += x * x;
  return std::sqrt(sum / std::max<std::size_t>(errors.size(), 1));
}

// Tracks against the truth, frame by frame. Errors count once the filter has converged: from
// 0.1 s on, and for the velocity not within `settle` seconds after a ball's strike, end of
// sliding or stop (the phase changes the filter must first detect). A ball's track is the
// nearest confirmed one when first seen; another track becoming the nearest is a swap, its track
// disappearing a loss.
struct Errors {
  std::vector<double> position, velocity;
  std::vector<double> moving_velocity;  // the velocity errors of balls moving faster than 1 cm/s
  int swaps = 0, lost = 0;
  std::map<std::size_t, int> identity;  // ball -> track id
  double settle = 0.3;

  void Add(const Scene& s, double t, const std::vector<TrackedBall>& tracks) {
    for (std::size_t i = 0; i < s.rest.size(); ++i) {
      const TrackedBall* nearest = nullptr;
      for (const TrackedBall& track : tracks) {
        if (track.confirmed && (!nearest || (track.position() - s.At(i, t)).norm() <
                                                (nearest->position() - s.At(i, t)).norm())) {
          nearest = &track;
        }
      }
      if (!nearest) continue;
      if (!identity.count(i)) identity[i] = nearest->id;
      const TrackedBall* own = nullptr;
      for (const TrackedBall& track : tracks) {
        if (track.id == identity[i]) own = &track;
      }
      if (!own) {
        ++lost;
        continue;
      }
      if (own != nearest) ++swaps;
      if (t < 0.1) continue;
      position.push_back((own->position() - s.At(i, t)).norm());
      bool settled = true;
      for (double change : s.phase_changes[i]) {
        settled = settled && !(t >= change && t < change + settle);
      }
      if (!settled) continue;
      const double error = (own->velocity() - s.VelocityAt(i, t)).norm();
      velocity.push_back(error);
      if (s.VelocityAt(i, t).norm() > 0.01) moving_velocity.push_back(error);
    }
  }
};

}  // namespace billiard::estimator::shots
