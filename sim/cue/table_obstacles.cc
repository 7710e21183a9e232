#include "sim/cue/table_obstacles.h"

#include <limits>

namespace billiard::cue {

std::vector<TableObstacle> TableObstacles(const table::TableGeometry& table) {
  constexpr double kNoEnd = std::numeric_limits<double>::infinity();
  const double L = table.length, W = table.width, w = table.rail_width, h = table.rail_height;
  using V = Eigen::Vector3d;
  return {
      {"the cloth", {V(0, 0, -kNoEnd), V(L, W, 0)}},
      {"the lower rail", {V(-w, -w, -kNoEnd), V(L + w, 0, h)}},
      {"the right rail", {V(L, -w, -kNoEnd), V(L + w, W + w, h)}},
      {"the upper rail", {V(-w, W, -kNoEnd), V(L + w, W + w, h)}},
      {"the left rail", {V(-w, -w, -kNoEnd), V(0, W + w, h)}},
  };
}

}  // namespace billiard::cue
