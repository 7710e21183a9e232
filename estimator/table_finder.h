// The playing surface in a camera frame, found without markers: the cloth, its four sides, and
// what they say of the camera.
//
// The cloth is the largest evenly coloured thing near the middle of a table camera's view, of any
// colour (green, blue, navy, red, grey). Its colour is the mode of the frame's colours weighted
// towards the image centre; its pixels are those of about that chromaticity (which vignetting and
// mixed lights leave nearly alone while they change the brightness), not across a strong edge
// (the cushion's nose, the rail), connected to the mode's largest region. Balls, chalk and hands
// on it are holes, filled; pockets and the cushions' noses are notches in its outline.
//
// The outline's four sides are straight lines in the image (a plane seen through a pinhole; lens
// distortion bends them a little): the convex hull reduced to four vertices says roughly where,
// and a line fitted (RANSAC, then least squares) to the outline points along the middle of each
// side, away from the corner pockets, says exactly. The corners are the lines' intersections,
// where the cloth would meet without pockets. Where a player, an arm or a cue hides part of a
// side, or the cushion's top joins the bed for a while, the outline along it is broken into
// straight stretches at different depths and the best supported line may bridge two of them.
// When no straight edge along both halves of the side confirms that line at full resolution, the
// side is the first of the other stretches (turned little from it) that one confirms, if a
// cushion's nose runs along most of the side inside it too; else the best supported line stands.
//
// The cloth covers the cushions too, so its outline may be their outer edge. The playing surface
// ends at the cushions' noses: inside each side, up to kMaxCushionWidth of the table's width in,
// the line through the edges (sharp changes of colour) at most places along both halves of the
// side: the edge of the cushion's face, in shadow or light. A row of balls against the cushion
// makes a line along one half at most. Where no such line is, the outline is the nose (a cushion
// seen from behind hides its face).
//
// A wide-angle lens bends the sides (barrel distortion bows them outward). Before the sides are
// fitted, the outline's points along them say how much (lens_estimate.h, the plumb-line method):
// where a lens clearly straightens them, the frame is redrawn as its pinhole sees it and the table
// is found there, its geometry (the homography, the inverse depth) kept in the pinhole's pixels and
// its corners and masks given in the frame's; every method taking or giving a pixel takes or gives
// the frame's.
//
// What the four corners give:
//   - A homography between the frame and the table's plane. The table is twice as long as it is
//     wide (pool, snooker and carom alike); which pair of sides is the long one comes from the
//     camera: the pinhole with square pixels and a centred principal point that the homography
//     implies must have the same focal length from both of Zhang's (2000) constraints when the
//     sides are assigned right. Where the view is too square-on for that to tell, the longer
//     pair in the image is the long side.
//   - The depth of every place on the table, up to a scale, whichever side is long: the inverse
//     depth of the plane's points is an affine function of the pixel (the third row of the
//     inverse homography). A ball's apparent radius is proportional to it (ball_scale.h).
//   - The view: overhead when the depth varies by less than kOverheadDepthRatio across the table.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "estimator/lens_estimate.h"

namespace billiard::estimator {

// A view is overhead when the farthest corner of the table is at most this much farther from the
// camera than the nearest (ball sizes then differ by at most as much across the table).
inline constexpr double kOverheadDepthRatio = 1.2;

enum class TableView { kOverhead, kOblique };
const char* TableViewName(TableView view);

// Where a table region comes from: its sides found in the frame (FindTable), a calibrated camera
// (table_fallback.h's TableSeenBy: nothing looked for), or the cloth alone where no table was
// found (table_fallback.h's ClothOnly: the balls on it, in image coordinates only).
enum class TableOrigin { kFound, kCalibrated, kClothOnly };
const char* TableOriginName(TableOrigin origin);

// The table search's resolution: the frame's longer side reduced to at most this many pixels.
inline constexpr double kTableSearchSize = 400.0;
// The search's reduction of a frame of `size`: an integer, since OpenCV's area averaging is much
// faster by whole factors.
inline int SearchReduction(const cv::Size& size) {
  return static_cast<int>(std::ceil(std::max(size.width, size.height) / kTableSearchSize));
}
// A side of the cloth's outline within this many search pixels of the frame's edge at both ends
// runs along it (the region's outline traced on the search's grid, the cloth's line fitted at
// full resolution within a pixel or two of it): the frame's edge, not the cloth's.
inline constexpr double kFrameEdgePx = 2.0;

// How far in from the cloth's outline the cushions' noses are looked for, in table widths.
inline constexpr double kMaxCushionWidth = 0.12;

struct TableRegion {
  // The corners of the playing surface (where the cushions' noses meet) [full-resolution px], in
  // order around the table. Through a lens (`lens.k1` != 0) a side between two corners is the
  // image of the pinhole's straight line, a curve (DistanceToSide).
  std::array<Eigen::Vector2d, 4> corners;
  // The corners of the cloth's outline, the cushions' tops included, in the same order.
  std::array<Eigen::Vector2d, 4> cloth_corners;
  // RMS distance [full-resolution px] of the outline's points along the middle of each side from
  // the side's fitted line: how straight the sides are (lens distortion, a cloth that is not the
  // table's) and how well they were found.
  double side_fit_rms_px = 0;
  // The lens the table was found through (lens_estimate.h): k1 = 0, a pinhole, unless its sides
  // were clearly bent.
  RadialLens lens;
  // Pinhole pixel (the frame's pixel where lens.k1 = 0, else lens.ToPinhole of it) from table
  // point (x along the long side in [0, 2], y along the short side in
  // [0, 1], homogeneous): the playing surface in units of its width.
  Eigen::Matrix3d image_from_table = Eigen::Matrix3d::Identity();
  // The inverse depth of the table's plane, relative to the table's centre: 1 / depth at pinhole
  // pixel (u, v) is inverse_depth.dot((u, v, 1)) / depth at the centre (InverseDepthAt takes the
  // frame's pixel; read at the frame's pixel directly, as BallScale does, it is off through a lens
  // by the little the depth changes over the lens's shift, nothing in an overhead view).
  Eigen::Vector3d inverse_depth = Eigen::Vector3d::UnitZ();
  TableView view = TableView::kOverhead;
  TableOrigin origin = TableOrigin::kFound;
  // The side (corner i to i + 1) beyond the frame's border, its corners inferred from the table's
  // proportions (table_partial.h); -1 where the four sides were seen.
  int side_out_of_frame = -1;
  // The largest over the smallest depth of the four corners.
  double depth_ratio = 1.0;
  // The cloth [255 where cloth] and the playing surface (the cloth with its holes filled) at
  // `mask_scale` of the full resolution.
  cv::Mat cloth, surface;
  double mask_scale = 1.0;
  // The cloth's dominant colour (BGR).
  cv::Vec3f cloth_colour;

  // Whether a full-resolution pixel is on the playing surface, at least `margin_px` inside it.
  bool Contains(const Eigen::Vector2d& pixel, double margin_px = 0.0) const;
  // Whether a full-resolution pixel is inside the cloth's outline, at least `margin_px` inside.
  bool InsideCloth(const Eigen::Vector2d& pixel, double margin_px = 0.0) const;
  // The places pockets may be [full-resolution px]: the corners of the playing surface and the
  // middles of its sides (which two are the long ones the frame may not tell).
  std::array<Eigen::Vector2d, 8> PocketPlaces() const;
  // Relative inverse depth (1 at the table's centre) at a full-resolution pixel.
  double InverseDepthAt(const Eigen::Vector2d& pixel) const;
  // The table point (x in [0, 2], y in [0, 1] on the surface) seen at a pixel.
  Eigen::Vector2d TableAt(const Eigen::Vector2d& pixel) const;
  // The homography's Jacobian at a pixel: pinhole pixels per table width, along the table's x
  // (column 0) and y (column 1).
  Eigen::Matrix2d JacobianAt(const Eigen::Vector2d& pixel) const;
  // Image pixels per table width at a pixel, along the direction the view does not foreshorten
  // (the larger singular value of the homography's Jacobian): how large things on the table at
  // that place look, in pixels, when seen square on.
  double PixelsPerWidthAt(const Eigen::Vector2d& pixel) const;
  // How far apart on the table two pixels are, in the pixels of PixelsPerWidthAt at their middle:
  // balls touching in an oblique view are closer in the image along the view than across it,
  // never on the table.
  double TableDistancePx(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
  // The distance [full-resolution px] of a pixel from side `side` (corner `side` to the next): from
  // its line, or through a lens from the image of the pinhole's line at the foot of the pixel's
  // pinhole image on it.
  double DistanceToSide(int side, const Eigen::Vector2d& pixel) const;
  // The centre of the table in the image.
  Eigen::Vector2d Centre() const;
  // The smallest rectangle of full-resolution pixels holding the cloth's outline.
  cv::Rect Bounds() const;
};

// A table found, or the one-line reason why none was; then, where the cloth was found but not
// its table (its outline not a quadrilateral, a side not straight, the corners not a plane's, the
// proportions not a table's: part of the table out of frame, a wide-angle lens, an arm across
// it), the cloth: `cloth` holds its masks, their scale and its colour, and no geometry.
// Beside it, the regions of the frame's next likeliest colours (as `cloth`, of the first): with
// more than half of a table out of the frame, the floor around it can outweigh its cloth, and
// which of them holds the balls tells (table_fallback.h's ClothWithBalls).
struct TableSearch {
  std::optional<TableRegion> table;
  std::string reason;
  std::optional<TableRegion> cloth;
  std::vector<TableRegion> other_cloths = {};
};

// The table in a BGR (CV_8UC3) frame. About 5 ms at 1280x720: the frame is searched at about 400
// pixels across; the lens estimate adds some 10 ms (about 150 evaluations of the sides' residual
// over some 700 outline points: 4 estimates of 1,300 points take 84 ms in lens_estimate_test),
// and a frame found through a lens is searched twice.
TableSearch FindTable(const cv::Mat& bgr);

// Whether a table found in a frame of `frame_size` was not seen whole: its cloth's outline runs
// along the frame's border (within the search's pixel or two), or a side beyond it was completed
// (table_partial.h).
bool CutByFrame(const TableRegion& table, const cv::Size& frame_size);

}  // namespace billiard::estimator
