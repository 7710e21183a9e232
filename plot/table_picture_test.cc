// The picture's data: the frame a reader finds a table point in, and the key of the paths (every
// ball that moved, by number, and no other).
#include "plot/table_picture.h"

#include <gtest/gtest.h>

#include "sim/table/table_geometry.h"

namespace billiard::plot {
namespace {

TablePicture Picture() {
  TablePicture pic;
  pic.table.length = 2.54;
  pic.table.width = 1.27;
  return pic;
}

PictureBall Ball(int id, std::vector<Eigen::Vector2d> path) {
  PictureBall b;
  b.id = id;
  b.path = std::move(path);
  return b;
}

TEST(TablePicture, ATablePointIsFoundAtFourHundredPixelsAMetre) {
  const TablePicture pic = Picture();
  EXPECT_EQ(TablePixel(pic, {0, 0}), Eigen::Vector2d(kMarginPx, kMarginPx + 400 * 1.27));
  EXPECT_EQ(TablePixel(pic, {2.54, 1.27}), Eigen::Vector2d(kMarginPx + 400 * 2.54, kMarginPx));
}

TEST(TablePicture, ThePathsKeyListsTheBallsThatMovedByNumber) {
  TablePicture pic = Picture();
  pic.balls.push_back(Ball(9, {{1, 1}, {1.2, 1}}));
  pic.balls.push_back(Ball(0, {{0.5, 0.5}, {1, 1}}));
  pic.balls.push_back(Ball(1, {{2, 0.3}, {2, 0.3}}));  // still
  pic.balls.push_back(Ball(3, {{2, 0.6}}));            // one point: still
  PictureBall dropped = Ball(5, {{1.5, 0.5}, {2.5, 0.1}});
  dropped.pocket = "lower_right";
  pic.balls.push_back(dropped);  // it moved, into a pocket: its path is drawn
  EXPECT_EQ(PathLegendIds(pic), (std::vector<int>{0, 5, 9}));
}

}  // namespace
}  // namespace billiard::plot
