// The table's region where its sides are not looked for or not found: from a calibrated camera,
// or the cloth alone.
//
// A rig calibrated once (`billiard calibrate`, with markers or from the table's corners:
// table_pose.h) knows where its table is: TableSeenBy projects the playing surface through the
// camera, so that a frame with an arm, a cue or a player across a side needs no table finding;
// only the cloth's colour is still read from the frame (FindTable's cloth, or the surface's own
// pixels where none is found). A frame whose table is not found and with no calibration still
// has its cloth (TableSearch::cloth): ClothOnly makes a region of it seen from overhead, whose
// balls are found and reported in image coordinates only (the region knows neither the table's
// size nor its perspective), with the reason no table was found: never nothing.
#pragma once

#include <array>
#include <opencv2/core.hpp>
#include <optional>

#include "estimator/table_finder.h"
#include "sim/camera/camera_model.h"
#include "sim/physics/parameters.h"

namespace billiard::estimator {

// The height of a cushion's nose over the ball's diameter: the WPA's equipment specifications
// (2001) put it at 62.5 % to 64.5 %; the middle.
inline constexpr double kNoseHeightOverBallDiameter = 0.635;

// The height of the cushions' noses above the cloth [m], for balls of `ball_radius` [m]: where the
// corners of the playing surface a camera sees are (the noses' lines meet there).
inline double NoseHeight(double ball_radius) {
  return kNoseHeightOverBallDiameter * 2 * ball_radius;
}

// A calibrated camera and the table it looks at.
struct CalibratedTable {
  camera::CameraModel camera;
  physics::TableParameters table;
  double nose_height = 0;  // [m] (NoseHeight)
};

// The table a calibrated camera sees in a BGR frame of its size: the playing surface's corners
// projected at the noses' height, the homography, depth and view they imply, origin kCalibrated;
// the cloth's masks and colour from FindTable where it finds the cloth, else the projected surface
// itself and the median colour on it. Its cloth's outline is the playing surface's: no ball's
// centre lies beyond the noses (a found table's cloth may include the cushions' tops, where a
// calibration puts a rail's diamonds and a pocket's liner off the table, as they are).
TableRegion TableSeenBy(const CalibratedTable& calibrated, const cv::Mat& bgr);

// The cloth alone (TableSearch::cloth) as a table region seen from overhead: its corners the
// smallest rectangle around the filled cloth, the homography a similarity onto it (uniform
// scale, no perspective), origin kClothOnly.
TableRegion ClothOnly(const TableRegion& cloth);

// The cloth the balls lie on in a BGR frame whose table was not found, as ClothOnly's region:
// of the regions of the frame's likeliest colours (`search.cloth`, then `search.other_cloths`),
// the one whose compact blobs of not-cloth are most surely balls of one size (ball_scale.h's
// ScaleFromBlobs: the rays of the outlines that agree on a radius), the likeliest colour where
// none has more. With more than half of the table out of the frame, or a long side, the floor
// beside it can be the frame's likeliest colour, and a straight-sided region: the balls are not
// on it. None where no region was found.
std::optional<TableRegion> ClothWithBalls(const cv::Mat& bgr, const TableSearch& search);

// The frame's edges in the order ClothAtFrameEdges gives them.
inline constexpr std::array<const char*, 4> kFrameEdges = {"left", "top", "right", "bottom"};

// Which part of the table a region of cloth shows: the share of each edge of the frame
// (kFrameEdges) along which its playing surface runs out of the frame, as the table does beyond
// it; all 0 for a table whole in the frame.
std::array<double, 4> ClothAtFrameEdges(const TableRegion& region);

}  // namespace billiard::estimator
