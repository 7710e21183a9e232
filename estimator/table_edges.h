// Straight edges along a table's sides, looked for at full resolution once the table finder
// (table_finder.h) knows roughly where the sides are: the cloth's outline to a fraction of a
// pixel, and the cushions' noses inside it.
//
// A side is given by a homography from the table's plane (a rectangle kTableAspect long and 1
// wide) to the image and which of its sides it is. Along it, at places on both of its halves away
// from the pockets, the colour is sampled on a line going inward a pixel at a time; its sharpest
// changes are the edges, and a straight edge is a line through the edges of many places on both
// halves (RANSAC, then least squares): a cushion runs along both halves, a row of balls against it
// along one at most.

#pragma once

#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

namespace billiard::estimator {

// The table's long side over its short side (pool, snooker and carom alike).
inline constexpr double kTableAspect = 2.0;

// The table's corners in its own plane, in the order a homography from it maps them to the image:
// the long side first when `long_first`, else the short side first.
std::array<Eigen::Vector2d, 4> TableCorners(bool long_first);

// The image line of side `side` (table corners side, side + 1) of `image_from_table`.
Eigen::Vector3d SideLine(const Eigen::Matrix3d& image_from_table, bool long_first, int side);

// The places along a side where edges are looked for, half on each of its halves (EdgeLine's
// `places` counts up to this many).
inline constexpr int kEdgePlaces = 48;

// A straight edge along a side: its homogeneous image line, at how many places along the side it
// was met, and its mean distance inward from the side's line [px] (negative: outward).
struct EdgeLine {
  Eigen::Vector3d line;
  int places = 0;
  double inward_px = 0;
  double rms_px = 0;  // of its edges from it
};

// The straight edges along side `side` of `image_from_table` between `from` and `to` table widths
// inward of it (negative: outward), best supported first; edges nearer the side's line than
// `clearance_px` are not counted.
std::vector<EdgeLine> EdgeLinesAlong(const cv::Mat& bgr, const Eigen::Matrix3d& image_from_table,
                                     bool long_first, int side, double from, double to,
                                     double clearance_px);

// The cloth's outline along a side, to a fraction of a pixel: the best supported straight edge
// within `search_px` of the side's line (the outline found at a lower resolution); none when there
// is no straight edge there.
std::optional<EdgeLine> ClothSide(const cv::Mat& bgr, const Eigen::Matrix3d& image_from_table,
                                  bool long_first, int side, double search_px);

// The nose of the cushion along side `side` of `cloth_from_table` (the cloth's outline), up to
// `max_cushion_width` table widths inward: the best supported straight edge, or the innermost
// nearly as well supported; none when there is none (a cushion seen from behind hides its face).
std::optional<EdgeLine> NoseLine(const cv::Mat& bgr, const Eigen::Matrix3d& cloth_from_table,
                                 bool long_first, int side, double max_cushion_width);

// The nose of a cushion seen from behind (the one nearest the camera in an oblique view): its top
// is of the cloth, so the cloth's outline is the cushion's back, and the nose is a faint line
// where the top meets the bed (a highlight along it, or a change of shade), too faint for each
// place's edge to pass NoseLine's threshold. So the colour's rate of change is gathered along every
// straight line across the band (a Hough transform over the two ends' offsets): the line whose
// median rate over the places of each half of the side is the highest, if it is kFaintEdges times
// the band's median. None when no line stands out.
std::optional<Eigen::Vector3d> FaintNoseLine(const cv::Mat& bgr,
                                             const Eigen::Matrix3d& cloth_from_table,
                                             bool long_first, int side, double max_cushion_width);

}  // namespace billiard::estimator
