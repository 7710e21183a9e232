// A table with part of it out of the frame: a phone held over a carom table, an overhead rig that
// does not cover the whole table. The cloth's outline then has three of the table's sides and the
// frame's border for the fourth, and the surface found is not a table's shape: shorter than a
// table where an end is out (a third out: 1.33 times as long as it is wide), a trapezoid where the
// border crosses the table turned (a long side out, the short sides cut at different lengths).
// The table's known proportions complete it: the playing surface is kTableAspect times as long as
// it is wide between the cushions' noses, so the unseen side lies that many times the seen
// opposite side's length (an end out) or that many times less (a long side out) along the sides
// beside the cut, measured in the seen side's scale.
//
// Along a side, the image of a distance on the table is projective: a point t along it (in the
// seen side's pixels per unit) is seen at d(t) = t / (1 + t / D), D the distance to where the two
// sides meet in the image (their vanishing point; D infinite and d = t where they are parallel,
// as from straight overhead). That takes the scale along the side at the seen side to be the
// scale across it, as it is for a camera looking down on the table (an overhead view,
// table_finder.h's kOverheadDepthRatio): the only views completed.
#pragma once

#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

namespace billiard::estimator {

// The least share of the cut sides' length that must be seen (the two sides' mean) to complete
// the table: less leaves the seen part as much a short strip of cloth as a table's end or half.
inline constexpr double kMinSeenShare = 0.5;

// The sides (corner i to i + 1) of a quadrilateral [px] that lie along the frame's border: both
// corners within `border_px` of the same edge of a frame of `size`.
std::vector<int> SidesAlongBorder(const std::array<Eigen::Vector2d, 4>& corners,
                                  const cv::Size& size, double border_px);

// The corners [px] of the whole rectangle `aspect` long whose seen part is `corners` (in order
// around it), cut by the frame's border along side `cut`: the sides beside the cut extended (see
// the top of the file) to the unseen side, read as an end out when the seen sides make that
// plausible, else as a long side out (the two readings never both are: a seen share between
// kMinSeenShare and 1 of an end's sides is longer than a long side's whole short sides). None when
// neither is: a side beside the cut as long as the whole side or longer, the two seen for less
// than kMinSeenShare of their length, or the sides meeting before the unseen side.
std::optional<std::array<Eigen::Vector2d, 4>> CompletedAcrossBorder(
    const std::array<Eigen::Vector2d, 4>& corners, int cut, double aspect);

}  // namespace billiard::estimator
