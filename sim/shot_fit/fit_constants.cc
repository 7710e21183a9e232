#include "sim/shot_fit/fit_constants.h"

#include <algorithm>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace billiard::shot_fit {

namespace {

const char* const kConstantNames[] = {"mu",      "rolling",          "spin",
                                      "cushion", "cushion_friction", "ball_ball"};

}  // namespace

Range ConstantRange(Constant c) {
  switch (c) {
    case Constant::kMu: return {0.02, 0.6};
    case Constant::kRolling: return {2e-4, 0.05};
    case Constant::kSpin: return {2e-4, 0.02};
    case Constant::kCushion: return {0.3, 0.99};
    case Constant::kCushionFriction: return {0.0, 0.4};
    case Constant::kBallBall: return {0.5, 1.0};
  }
  return {0.0, 0.0};
}

const char* ConstantName(Constant constant) { return kConstantNames[static_cast<int>(constant)]; }

std::vector<Constant> ParseConstants(const std::string& list) {
  std::vector<Constant> out;
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name.empty()) continue;
    const auto* end = std::end(kConstantNames);
    const auto* found = std::find(std::begin(kConstantNames), end, name);
    if (found == end) {
      throw std::invalid_argument(
          "unknown constant \"" + name +
          "\" (known: mu, rolling, spin, cushion, cushion_friction, ball_ball)");
    }
    const auto c = static_cast<Constant>(found - std::begin(kConstantNames));
    if (std::find(out.begin(), out.end(), c) != out.end())
      throw std::invalid_argument("constant \"" + name + "\" named twice");
    out.push_back(c);
  }
  return out;
}

double ConstantValue(const physics::ModelParameters& p, Constant constant) {
  switch (constant) {
    case Constant::kMu: return p.contact.mu;
    case Constant::kRolling: return p.RollingResistance();
    case Constant::kSpin: return p.contact.patch_radius;
    case Constant::kCushion: return p.collision.cushion_restitution;
    case Constant::kCushionFriction: return p.collision.cushion_friction;
    case Constant::kBallBall: return p.collision.ball_restitution;
  }
  return 0.0;
}

physics::ModelParameters WithConstants(const physics::ModelParameters& p,
                                       const std::vector<Constant>& constants,
                                       const std::vector<double>& values) {
  if (constants.size() != values.size())
    throw std::invalid_argument("WithConstants: one value per constant");
  physics::ModelParameters out = p;
  const double r = p.ball.radius;
  double rolling = p.RollingResistance();
  for (std::size_t i = 0; i < constants.size(); ++i) {
    switch (constants[i]) {
      case Constant::kMu: out.contact.mu = values[i]; break;
      case Constant::kRolling: rolling = values[i]; break;
      case Constant::kSpin: out.contact.patch_radius = values[i]; break;
      case Constant::kCushion: out.collision.cushion_restitution = values[i]; break;
      case Constant::kCushionFriction: out.collision.cushion_friction = values[i]; break;
      case Constant::kBallBall: out.collision.ball_restitution = values[i]; break;
    }
  }
  // mu_r = a d / (5 r) kept (or set) after a possibly new a.
  out.contact.d = 5.0 * r * rolling / out.contact.patch_radius;
  if (out.contact.d > 1.0) {
    out.contact.d = 1.0;
    out.contact.patch_radius = 5.0 * r * rolling;
  }
  return out;
}

}  // namespace billiard::shot_fit
