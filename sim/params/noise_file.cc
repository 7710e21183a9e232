#include "sim/params/noise_file.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace billiard::params {

namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kMillimetre = 1e-3;

}  // namespace

std::string FormatNoise(const ExecutionNoise& noise) {
  const nlohmann::ordered_json j = {{"name", noise.name},
                                    {"source", noise.source},
                                    {"speed_fraction", noise.speed},
                                    {"speed_mps", noise.speed_absolute},
                                    {"heading_deg", noise.heading / kDegree},
                                    {"tip_mm", noise.tip_offset / kMillimetre},
                                    {"elevation_deg", noise.elevation / kDegree}};
  return j.dump(2) + "\n";
}

}  // namespace billiard::params
