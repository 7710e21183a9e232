#include "sim/cue/body.h"

#include <algorithm>
#include <limits>

namespace billiard::cue {

namespace {

// How far the horizontal projection of `p` lies inside the noses' rectangle grown by
// `overhang` (< 0: outside, by the nearest side's distance).
double InsideRectangle(const table::TableGeometry& table, double overhang,
                       const Eigen::Vector3d& p) {
  return std::min({p.x() + overhang, table.length + overhang - p.x(), p.y() + overhang,
                   table.width + overhang - p.y()});
}

// The least of the margins, named.
BodyMargin Least(std::initializer_list<BodyMargin> margins) {
  return *std::min_element(
      margins.begin(), margins.end(),
      [](const BodyMargin& a, const BodyMargin& b) { return a.distance < b.distance; });
}

BodyMargin GantryMargin(const table::TableGeometry& table, const PlacedCue& cue,
                        const Robot& robot) {
  const Gantry& gantry = *robot.gantry;
  const Eigen::Vector3d carriage = cue.At(robot.bridge), butt = cue.At(cue.shape.length);
  return Least(
      {{InsideRectangle(table, gantry.overhang, carriage), "the carriage beyond its rectangle", robot.bridge},
       {InsideRectangle(table, gantry.overhang, butt), "the butt beyond the gantry", cue.shape.length},
       {carriage.z() - gantry.clearance, "the carriage below its clearance", robot.bridge}});
}

BodyMargin ArmMargin(const PlacedCue& cue, const Robot& robot) {
  const Arm& arm = *robot.arm;
  return {arm.reach - (cue.At(robot.bridge) - arm.base).norm(),
          "the gripper beyond the arm's reach", robot.bridge};
}

}  // namespace

BodyMargin BodyClearance(const table::TableGeometry& table, const PlacedCue& cue,
                         const Robot& robot) {
  if (robot.gantry) return GantryMargin(table, cue, robot);
  if (robot.arm) return ArmMargin(cue, robot);
  return {std::numeric_limits<double>::infinity(), ""};
}

}  // namespace billiard::cue
