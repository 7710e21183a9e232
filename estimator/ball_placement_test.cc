// Where a ball may lie, on table regions built by hand: the near cushion of an oblique view is
// the side of the largest inverse depth, and it hides what lies beyond its line less a margin;
// an overhead view hides nothing.
#include "estimator/ball_placement.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "estimator/table_edges.h"
#include "sim/camera/camera_model.h"

namespace billiard::estimator {
namespace {

// A table seen from its bottom side: the far side (top) shorter, the inverse depth growing down
// the frame (1 / depth = 0.5 + 0.002 v, relative).
TableRegion ObliqueTable() {
  TableRegion table;
  table.view = TableView::kOblique;
  table.corners = {{{200, 100}, {600, 100}, {700, 400}, {100, 400}}};
  table.cloth_corners = table.corners;
  table.inverse_depth = Eigen::Vector3d(0.0, 0.002, 0.5);
  // The table's centre at (400, 250): x = 2 along the long side, y = 1 across.
  table.image_from_table << 200, 0, 200, 0, 300, 100, 0, 0, 1;
  return table;
}

TEST(BallPlacement, TheNearCushionHidesWhatLiesBeyondItsLine) {
  const Occluder near = NearCushion(ObliqueTable(), 20.0);
  // The bottom side, y = 400, seen from above: what is below it less the margin, max(1.5 px,
  // 0.1 of a 20 px radius) = 2 px, is hidden.
  EXPECT_NEAR(near.normal.x(), 0.0, 1e-12);
  EXPECT_NEAR(near.normal.y(), 1.0, 1e-12);
  EXPECT_NEAR(near.offset, 400.0, 1e-9);
  EXPECT_NEAR(near.margin_px, 2.0, 1e-12);
  EXPECT_TRUE(near.Hides({400, 398.5}));
  EXPECT_FALSE(near.Hides({400, 397.5}));
  EXPECT_FALSE(near.Hides({400, 250}));
  // A small ball's margin is the line's own 1.5 px.
  EXPECT_NEAR(NearCushion(ObliqueTable(), 5.0).margin_px, 1.5, 1e-12);
}

TEST(BallPlacement, TheNearSideIsTheOneOfTheLargestInverseDepth) {
  TableRegion table = ObliqueTable();
  // Seen from the top instead: the top side is near, and the normal points up, away from the
  // table.
  table.inverse_depth = Eigen::Vector3d(0.0, -0.002, 1.5);
  const Occluder near = NearCushion(table, 20.0);
  EXPECT_NEAR(near.normal.y(), -1.0, 1e-12);
  EXPECT_NEAR(near.offset, -100.0, 1e-9);
  EXPECT_TRUE(near.Hides({400, 101}));
  EXPECT_FALSE(near.Hides({400, 103}));
}

TEST(BallPlacement, AnOverheadViewHidesNothing) {
  TableRegion table = ObliqueTable();
  table.view = TableView::kOverhead;
  const Occluder none = NearCushion(table, 20.0);
  EXPECT_FALSE(none.Hides({400, 399}));
  EXPECT_FALSE(none.Hides({400, 1000}));
}

// A 2.54 x 1.27 m table (WPA 9-ft) seen by a pinhole `elevation_deg` above the cloth from beside
// its long side y = 0, as the finder gives it: the corners' homography and inverse depth.
constexpr double kLength = 2.54, kWidth = 1.27, kBall = 0.028575;

camera::CameraModel Beside(double elevation_deg) {
  const Eigen::Vector3d middle(0.5 * kLength, 0.5 * kWidth, 0.0);
  const double e = elevation_deg * M_PI / 180.0;
  const Eigen::Vector3d back(0, -std::cos(e), std::sin(e));
  return camera::CameraModel::LookingAt(middle + 3.2 * back, middle, 1280, 720, 1.0);
}

TableRegion SeenBy(const camera::CameraModel& c) {
  TableRegion table;
  table.view = TableView::kOblique;
  std::vector<cv::Point2f> from, to;
  for (const auto& t : TableCorners(true)) {
    const Eigen::Vector2d p = c.Project(Eigen::Vector3d(t.x() * kWidth, t.y() * kWidth, 0.0));
    from.emplace_back(static_cast<float>(t.x()), static_cast<float>(t.y()));
    to.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
  }
  const cv::Mat h = cv::getPerspectiveTransform(from, to);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) table.image_from_table(i, j) = h.at<double>(i, j);
  }
  for (int i = 0; i < 4; ++i) table.corners[i] = Eigen::Vector2d(to[i].x, to[i].y);
  table.cloth_corners = table.corners;
  const Eigen::Vector3d w = table.image_from_table.inverse().row(2).transpose();
  table.inverse_depth = w / w.dot(table.Centre().homogeneous());
  return table;
}

// The ball's apparent radius [px]: its centre to its limb across the view.
double ApparentRadius(const camera::CameraModel& c, const Eigen::Vector3d& centre) {
  return (c.Project(centre + kBall * Eigen::Vector3d::UnitX()) - c.Project(centre)).norm();
}

// Where a ball touches the cloth is where the camera sees it, from the homography alone: against
// the camera's projection of the contact point, within kGroundRadii of a radius, from 15 to 60
// degrees (the centre itself is 0.97 of a radius away from 15 degrees, 0.5 from 60). Measured:
// at most 0.02 of a radius from 15 degrees, 0.04 from 30, 0.07 from 45, 0.13 from 60 (at the
// table's ends the image's vertical leans away from the view's direction, more the higher the
// camera; the test is used only where the centre is beyond the cloth, in a low view).
TEST(BallPlacement, WhereABallTouchesTheClothIsSeenWhereTheCameraPutsIt) {
  constexpr double kGroundRadii = 0.15;
  for (const double elevation : {15.0, 20.0, 30.0, 45.0, 60.0}) {
    const camera::CameraModel c = Beside(elevation);
    const TableRegion table = SeenBy(c);
    for (const double x : {0.1, 1.27, 2.44}) {
      for (const double y : {0.05, 0.6, 1.22}) {
        const Eigen::Vector3d centre(x, y, kBall);
        const double r = ApparentRadius(c, centre);
        const Eigen::Vector2d seen = c.Project(centre), ground = c.Project({x, y, 0.0});
        EXPECT_LT((GroundPoint(table, seen, r) - ground).norm(), kGroundRadii * r)
            << elevation << " deg at " << x << ", " << y;
      }
    }
  }
}

// From 15 degrees a ball against the far cushion has its centre 0.7 of a radius beyond the
// cushion's foot, where a cushion's top begins: on the table where it touches the cloth, while
// what lies a ball's diameter beyond the nose, on the cushion's top, is not.
TEST(BallPlacement, ABallAgainstTheFarCushionInALowViewIsOnTheTable) {
  const camera::CameraModel c = Beside(15.0);
  const TableRegion table = SeenBy(c);
  const Eigen::Vector3d against(1.0, kWidth - kBall, kBall), beyond(1.0, kWidth + kBall, kBall);
  const double r = ApparentRadius(c, against);
  EXPECT_FALSE(table.InsideCloth(c.Project(against), -0.5 * r)) << "the test's premise";
  EXPECT_TRUE(OnTable(table, c.Project(against), r));
  EXPECT_FALSE(OnTable(table, c.Project(beyond), r));
  // Seen from overhead the centre is where the ball touches the cloth.
  TableRegion overhead = table;
  overhead.view = TableView::kOverhead;
  EXPECT_FALSE(OnTable(overhead, c.Project(against), r));
}

}  // namespace
}  // namespace billiard::estimator
