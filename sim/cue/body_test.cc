#include "sim/cue/body.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/params/table_specs.h"

namespace billiard::cue {
namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kR = 0.028575;

class BodyTest : public ::testing::Test {
 protected:
  BodyTest() : table_(table::BuildTable(params::LoadTableSpec(params::kDefaultTable))) {
    robot_.cue = {0.74, 0.0065, 0.0108};
    robot_.bridge = 0.2;
  }
  // A centre stroke on a ball at (x, y), heading `heading`, raised by `elevation`.
  PlacedCue Placed(double x, double y, double heading, double elevation) const {
    return PlaceCue({x, y}, kR, {2.0, heading, 0.0, 0.0, elevation}, robot_.cue);
  }
  table::TableGeometry table_;
  Robot robot_;
};

TEST_F(BodyTest, APlayerHasNoBody) {
  const BodyMargin margin = BodyClearance(table_, Placed(0.1, 0.1, 0.0, 0.0), robot_);
  EXPECT_TRUE(std::isinf(margin.distance));
  EXPECT_EQ(margin.what, "");
}

// A centre stroke holds the carriage at R + bridge behind the centre along the cue's axis: at
// height R + (R + bridge) sin(elevation).
TEST_F(BodyTest, TheCarriageAboveItsClearance) {
  robot_.gantry = Gantry{0.6, 0.05};
  for (double elevation : {0.0, 5 * kDegree, 20 * kDegree}) {
    const BodyMargin margin = BodyClearance(table_, Placed(1.27, 0.635, 0.3, elevation), robot_);
    EXPECT_NEAR(margin.distance, kR + (kR + 0.2) * std::sin(elevation) - 0.05, 1e-15);
    EXPECT_EQ(margin.what, "the carriage below its clearance");
  }
}

// A ball D from the lower nose, struck away from it: the butt lies (R + length) cos(elevation)
// behind the centre, beyond the nose by that less D; the rectangle reaches `overhang` past it.
TEST_F(BodyTest, TheButtWithinTheGantry) {
  robot_.gantry = Gantry{0.1, 0.0};
  const double D = 0.3;
  for (double elevation : {0.0, 30 * kDegree, 60 * kDegree}) {
    const BodyMargin margin = BodyClearance(table_, Placed(1.27, D, M_PI / 2, elevation), robot_);
    const double beyond = (kR + 0.74) * std::cos(elevation) - D;
    EXPECT_NEAR(margin.distance, 0.1 - beyond, 1e-15);
    EXPECT_EQ(margin.what, "the butt beyond the gantry");
  }
  robot_.gantry->overhang = 0.0;
  const BodyMargin carriage = BodyClearance(table_, Placed(1.27, 0.1, M_PI / 2, 0.0), robot_);
  EXPECT_NEAR(carriage.distance, 0.1 - (kR + 0.74), 1e-15) << "the butt is the farther out";
}

TEST_F(BodyTest, TheGripperWithinTheArmsReach) {
  robot_.arm = Arm{Eigen::Vector3d(1.27, -0.5, 0.5), 0.9};
  const PlacedCue cue = Placed(1.27, 0.3, M_PI / 2, 10 * kDegree);
  const Eigen::Vector3d gripper =
      Eigen::Vector3d(1.27, 0.3, kR) + (kR + 0.2) * cue.back;  // R + bridge behind the centre
  const BodyMargin margin = BodyClearance(table_, cue, robot_);
  EXPECT_NEAR(margin.distance, 0.9 - (gripper - robot_.arm->base).norm(), 1e-15);
  EXPECT_EQ(margin.what, "the gripper beyond the arm's reach");
}

}  // namespace
}  // namespace billiard::cue
