// Where a ball may lie, on table regions built by hand: the near cushion of an oblique view is
// the side of the largest inverse depth, and it hides what lies beyond its line less a margin;
// an overhead view hides nothing.
#include "estimator/ball_placement.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace billiard::estimator
