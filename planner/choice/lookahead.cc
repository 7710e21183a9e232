#include "planner/choice/lookahead.h"

#include <algorithm>
#include <cmath>

#include "planner/choice/scene_balls.h"
#include "planner/pot/pot_geometry.h"

namespace billiard::choice {

namespace {

// The least heading tolerance used against a zero heading spread [rad].
constexpr double kTinySpread = 1e-9;
// The least share of a pocket's width a ball entering at a slant still sees.
constexpr double kLeastForeshortening = 0.2;
constexpr double kDegree = M_PI / 180.0;

}  // namespace

double EasyPotEstimate(double radius, const std::vector<table::SceneBall>& balls, int ball,
                       const table::Pocket& pocket, const params::ExecutionNoise& noise,
                       double max_cut_deg) {
  const table::SceneBall* cue = FindBall(balls, 0);
  const table::SceneBall* object = FindBall(balls, ball);
  if (!cue || !object) return 0.0;
  const Eigen::Vector2d c = Position(*cue), o = Position(*object);
  const Eigen::Vector2d to_pocket = pocket.centre - o;
  const double pocket_distance = to_pocket.norm();
  if (pocket_distance <= 0) return 1.0;
  const Eigen::Vector2d departure = to_pocket / pocket_distance;
  const Eigen::Vector2d ghost = pot::GhostBall(o, departure, radius);
  const double cue_distance = (ghost - c).norm();
  if (cue_distance <= 0) return 0.0;
  const Eigen::Vector2d approach = (ghost - c) / cue_distance;
  const double cut = pot::CutAngle(approach, departure);
  if (cut > max_cut_deg * kDegree) return 0.0;
  const double clearance = 2 * radius;
  if (!pot::BallsAcross(balls, c, ghost, clearance, {0, ball}).empty()) return 0.0;
  if (!pot::BallsAcross(balls, o, pocket.centre, clearance, {0, ball}).empty()) return 0.0;
  const double half_width = 0.5 * (pocket.capture_b - pocket.capture_a).norm() - radius;
  const double foreshortening =
      std::max(kLeastForeshortening, std::abs(departure.dot(pocket.inward)));
  const double object_tolerance = std::max(0.0, half_width * foreshortening) / pocket_distance;
  const double heading_tolerance =
      object_tolerance * 2 * radius * std::cos(cut) / cue_distance;
  const double spread = std::max(noise.heading, kTinySpread);
  return std::erf(heading_tolerance / (std::sqrt(2.0) * spread));
}

double BestNextShotValue(const table::TableGeometry& table, double radius,
                         const std::vector<table::SceneBall>& balls, rules::Rules rules,
                         const params::ExecutionNoise& noise) {
  const rules::Ruleset& ruleset = rules::RulesetOf(rules);
  if (ruleset.RackOver(balls)) return 1.0;
  if (!FindBall(balls, 0)) return 0.0;
  double best = 0.0;
  for (int ball : ruleset.LegalTargets(balls)) {
    for (const table::Pocket& pocket : table.pockets) {
      best = std::max(best, EasyPotEstimate(radius, balls, ball, pocket, noise));
    }
  }
  return best;
}

}  // namespace billiard::choice
