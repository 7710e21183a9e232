#include "sim/params/constants_uncertainty.h"

#include <stdexcept>

#include "sim/params/parameter_sets.h"

namespace billiard::params {

namespace {

// The cue's numbers a draw may change: its physics, not the robot's limits.
bool DrawnCueKey(const std::string& key) {
  return key == "cue.mass" || key == "cue.tip_restitution" || key == "cue.end_mass";
}

bool StartsWith(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace

double* ConstantByKey(physics::ModelParameters& p, const std::string& key) {
  const bool drawn = StartsWith(key, "contact.") || StartsWith(key, "collision.") || DrawnCueKey(key);
  return drawn ? ParameterByKey(p, key) : nullptr;
}

physics::ModelParameters SampledConstants(const physics::ModelParameters& p,
                                          const std::function<double()>& unit_normal) {
  if (p.uncertainty.sd.empty()) return p;
  for (int draw = 0; draw < kMaxConstantDraws; ++draw) {
    physics::ModelParameters sampled = p;
    for (const auto& [key, sd] : p.uncertainty.sd) {
      double* value = ConstantByKey(sampled, key);
      if (value == nullptr) throw std::invalid_argument(p.name + ": cannot draw " + key);
      *value += sd * unit_normal();
    }
    try {
      physics::ValidateParameters(sampled);
      return sampled;
    } catch (const std::invalid_argument&) {
      // Outside the physical range: the truncated normal draws again.
    }
  }
  return p;
}

}  // namespace billiard::params
