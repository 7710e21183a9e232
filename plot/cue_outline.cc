#include "plot/cue_outline.h"

#include <cmath>
#include <cstdio>

namespace billiard::plot {

namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kMillimetre = 1e-3;

}  // namespace

std::array<Eigen::Vector2d, 4> OutlineCorners(const CueOutline& cue) {
  const Eigen::Vector2d forward = (cue.tip - cue.butt).normalized();
  const Eigen::Vector2d left(-forward.y(), forward.x());
  return {cue.tip + cue.tip_radius * left, cue.butt + cue.butt_radius * left,
          cue.butt - cue.butt_radius * left, cue.tip - cue.tip_radius * left};
}

std::string CueLabel(const CueOutline& cue) {
  char text[256];
  if (cue.elevation == 0.0) {
    std::snprintf(text, sizeof text, "cue level");
  } else {
    std::snprintf(text, sizeof text, "cue at %.2f deg", cue.elevation / kDegree);
  }
  std::string label = text;
  if (!cue.nearest) return label;
  if (cue.distance > 0.0) {
    std::snprintf(text, sizeof text, ", clears %s by %.1f mm", cue.nearest_what.c_str(),
                  cue.distance / kMillimetre);
  } else {
    std::snprintf(text, sizeof text, ", meets %s, %.1f mm into it", cue.nearest_what.c_str(),
                  -cue.distance / kMillimetre);
  }
  return label + text;
}

}  // namespace billiard::plot
