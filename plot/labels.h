// Where the numbers beside the balls go, so that in a cluster (a rack, balls frozen together)
// no number covers another or a ball: each label takes the first of the places round its ball
// (upper right first, then round the clock, then a ring further out) whose box meets no label
// placed before it and no ball; where none is free, the place that covers least. Placed in the
// order given, so the same balls give the same picture. A greedy placement of point labels
// (Christensen, Marks and Shieber 1995, "An empirical study of algorithms for point-feature
// label placement", ACM Trans. Graphics 14(3)) on a fixed set of candidate places.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace billiard::plot {

struct LabelRequest {
  Eigen::Vector2d centre;  // the ball's centre [px]
  Eigen::Vector2d size;    // the text's box, width and height [px]
};

// A label's box, top left and bottom right [px].
struct LabelBox {
  Eigen::Vector2d min, max;
  bool Overlaps(const LabelBox& o) const;
};

// The boxes of `labels`, in their order, for balls of radius `radius` [px] at every label's
// centre (and at `other_balls`, which have no label).
std::vector<LabelBox> PlaceLabels(const std::vector<LabelRequest>& labels, double radius,
                                  const std::vector<Eigen::Vector2d>& other_balls = {});

}  // namespace billiard::plot
