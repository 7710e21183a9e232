#include "sim/params/execution_noise.h"

#include <cmath>
#include <stdexcept>

#include "sim/params/strict_json.h"

namespace billiard::params {

namespace internal {
const std::vector<std::pair<std::string, std::string>>& BuiltinNoiseJson();
}

namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kMillimetre = 1e-3;
// A tip offset past this fraction of the radius would miss the ball.
constexpr double kTipLimit = 0.95;

}  // namespace

std::vector<std::string> BuiltinNoiseNames() {
  std::vector<std::string> names;
  for (const auto& [name, json] : internal::BuiltinNoiseJson()) names.push_back(name);
  return names;
}

ExecutionNoise ParseNoise(const std::string& json_text, const std::string& origin) {
  const nlohmann::json j = internal::ParseObject(json_text, origin, "a noise model");
  double speed_fraction = 0, speed_mps = 0, heading_deg = 0, tip_mm = 0, elevation_deg = 0;
  internal::ReadSection(j, "",
                        {{"speed_fraction", &speed_fraction},
                         {"speed_mps", &speed_mps},
                         {"heading_deg", &heading_deg},
                         {"tip_mm", &tip_mm},
                         {"elevation_deg", &elevation_deg}},
                        origin, {"name", "source"});
  for (double spread : {speed_fraction, speed_mps, heading_deg, tip_mm, elevation_deg}) {
    if (!std::isfinite(spread) || spread < 0) {
      throw std::invalid_argument(origin + ": a spread must be a finite number >= 0");
    }
  }
  ExecutionNoise noise;
  noise.name = internal::ReadText(j, "name", origin, origin);
  noise.source = internal::ReadText(j, "source", "", origin);
  noise.speed = speed_fraction;
  noise.speed_absolute = speed_mps;
  noise.heading = heading_deg * kDegree;
  noise.tip_offset = tip_mm * kMillimetre;
  noise.elevation = elevation_deg * kDegree;
  return noise;
}

ExecutionNoise LoadNoise(const std::string& name_or_path) {
  return ParseNoise(internal::BuiltinOrFileText(internal::BuiltinNoiseJson(), name_or_path,
                                                "noise model", "model"),
                    name_or_path);
}

physics::CueStroke Perturbed(physics::CueStroke stroke, const ExecutionNoise& noise,
                             double ball_radius, const std::function<double()>& unit_normal) {
  stroke.speed *= 1.0 + noise.speed * unit_normal();
  stroke.heading += noise.heading * unit_normal();
  stroke.tip_side += noise.tip_offset * unit_normal();
  stroke.tip_height += noise.tip_offset * unit_normal();
  if (noise.elevation > 0) stroke.elevation = std::abs(stroke.elevation + noise.elevation * unit_normal());
  if (noise.speed_absolute > 0) stroke.speed = std::abs(stroke.speed + noise.speed_absolute * unit_normal());
  const double offset = std::hypot(stroke.tip_side, stroke.tip_height);
  const double limit = kTipLimit * ball_radius;
  if (offset > limit) {
    stroke.tip_side *= limit / offset;
    stroke.tip_height *= limit / offset;
  }
  return stroke;
}

}  // namespace billiard::params
