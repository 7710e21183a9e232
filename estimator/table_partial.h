// A table with one end out of the frame: a phone held over a carom table, an overhead rig that
// does not cover the whole table. The cloth's outline then has three of the table's sides and the
// frame's border for the fourth, and the surface found is shorter than a table (a third out: 1.33
// times as long as it is wide). The table's known proportions complete it: the playing surface is
// kTableAspect times as long as it is wide between the cushions' noses, so the unseen end lies
// that far along the two long sides from the seen end, measured in the seen end's width.
//
// Along a side, the image of a distance on the table is projective: a point t along it (in the
// seen end's pixels per unit) is seen at d(t) = t / (1 + t / D), D the distance to where the two
// long sides meet in the image (their vanishing point; D infinite and d = t where they are
// parallel, as from straight overhead). That takes the scale along the side at the seen end to
// be the scale across it, as it is for a camera looking down on the table (an overhead view,
// table_finder.h's kOverheadDepthRatio): the only views completed.
#pragma once

#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

namespace billiard::estimator {

// The least share of the table's length that must be seen to complete it: less leaves the
// seen part as much a short strip of cloth as a table's end.
inline constexpr double kMinSeenShare = 0.5;

// The sides (corner i to i + 1) of a quadrilateral [px] that lie along the frame's border: both
// corners within `border_px` of the same edge of a frame of `size`.
std::vector<int> SidesAlongBorder(const std::array<Eigen::Vector2d, 4>& corners,
                                  const cv::Size& size, double border_px);

// The corners [px] of the whole rectangle kTableAspect long whose seen part is `corners` (in
// order around it), cut by the frame's border along side `cut`: the sides beside the cut are the
// long ones, extended (see the top of the file) to the unseen end. None when the seen part is
// not such an end: its long sides as long as a table's or longer, seen for less than
// kMinSeenShare of their length, or the sides meeting before the unseen end.
std::optional<std::array<Eigen::Vector2d, 4>> CompletedAcrossBorder(
    const std::array<Eigen::Vector2d, 4>& corners, int cut, double aspect);

}  // namespace billiard::estimator
