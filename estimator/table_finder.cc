#include "estimator/table_finder.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "estimator/table_cloth.h"
#include "estimator/outline_stretches.h"
#include "estimator/table_edges.h"
#include "estimator/table_partial.h"

namespace billiard::estimator {

namespace {

// The cloth must cover this fraction of the frame at least.
constexpr double kMinClothFraction = 0.04;
// The outline's sides: the hull is reduced to four vertices with a tolerance growing from
// kFirstPolygonTolerance of its perimeter (outline_stretches.h fits each side).
constexpr double kFirstPolygonTolerance = 0.01, kPolygonToleranceStep = 0.005,
                 kLastPolygonTolerance = 0.3;
// A stretch other than the best supported is taken for the side only when the nose found inside
// it is met at kOtherStretchNose of the places along the side at least (table_edges.h).
constexpr double kOtherStretchNose = 0.6;
// The outline found at the search resolution is refined within kOutlineSearchPx pixels of that
// resolution of it (its barrier and opening leave it a pixel or two inside).
constexpr double kOutlineSearchPx = 3.0;
// A camera's focal length is between kMinFocal and kMaxFocal image widths (a field of view from
// 118 to 19 degrees); the two of Zhang's constraints agree within kFocalAgreement for the right
// assignment of the long sides (an overhead view makes them 0 / 0: no camera, no answer).
constexpr double kMinFocal = 0.3, kMaxFocal = 3.0;
constexpr double kFocalAgreement = 1.3;
// Seen from overhead, the playing surface found is the table's (kTableAspect long over wide)
// within a factor of kOverheadAspectTolerance (the dev frames' are 1.93 to 2.05); else it is
// something else: a sheet of paper, a chart, a screen. And the cloth is not white: a cloth's L*
// is below kMaxClothLightness, or its chroma above kMinClothChroma (a grey cloth under bright
// light reads L* 76).
constexpr double kOverheadAspectTolerance = 1.25;
constexpr double kMaxClothLightness = 85.0, kMinClothChroma = 10.0;
// The cloth's colours tried (ClothColours): the likeliest, then the next two (a low camera sees
// the wall behind the table and the floor before it, each of its own colour).
constexpr std::size_t kClothColours = 3;
// The homography from the table (long side along x when `long_first`, else along y first and
// then turned so that x is the long side) to the image of `corners`.
Eigen::Matrix3d ImageFromTable(const std::array<Eigen::Vector2d, 4>& corners, bool long_first) {
  std::vector<cv::Point2f> table, image;
  for (const auto& c : TableCorners(long_first)) {
    table.emplace_back(static_cast<float>(c.x()), static_cast<float>(c.y()));
  }
  for (const auto& c : corners) {
    image.emplace_back(static_cast<float>(c.x()), static_cast<float>(c.y()));
  }
  const cv::Mat h = cv::getPerspectiveTransform(table, image);
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m(i, j) = h.at<double>(i, j);
  }
  return m;
}

// The squared focal lengths of the pinhole (square pixels, principal point at the image centre)
// a homography from a plane implies, from each of Zhang's (2000) two constraints on the rotation
// (its first two columns orthogonal, of equal length). Negative or infinite when the homography
// allows no such camera, or cannot tell (an overhead view).
std::pair<double, double> FocalLengthsSquared(const Eigen::Matrix3d& image_from_table,
                                              const cv::Size& size) {
  Eigen::Matrix3d centred = Eigen::Matrix3d::Identity();
  centred(0, 2) = -0.5 * (size.width - 1);
  centred(1, 2) = -0.5 * (size.height - 1);
  const Eigen::Matrix3d h = centred * image_from_table;
  const double orthogonal = -(h(0, 0) * h(0, 1) + h(1, 0) * h(1, 1)) / (h(2, 0) * h(2, 1));
  const double equal =
      (h(0, 0) * h(0, 0) + h(1, 0) * h(1, 0) - h(0, 1) * h(0, 1) - h(1, 1) * h(1, 1)) /
      (h(2, 1) * h(2, 1) - h(2, 0) * h(2, 0));
  return {orthogonal, equal};
}

// The corners where each side meets the previous one; false when two are parallel.
bool Intersections(const std::array<Eigen::Vector3d, 4>& lines,
                   std::array<Eigen::Vector2d, 4>* corners) {
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d corner = lines[(i + 3) % 4].cross(lines[i]);
    if (std::abs(corner.z()) < 1e-12 * corner.head<2>().norm()) return false;
    (*corners)[i] = corner.hnormalized();
  }
  return true;
}

// The largest over the smallest depth of the quadrilateral's corners, seen as a rectangle in a
// plane (whichever pair of sides is the long one): 0 when they cannot be one.
double DepthRatio(const std::array<Eigen::Vector2d, 4>& corners) {
  const Eigen::Vector3d inverse_depth = ImageFromTable(corners, true).inverse().row(2).transpose();
  double nearest = 0, farthest = HUGE_VAL;
  for (const auto& corner : corners) {
    const double w = inverse_depth.dot(corner.homogeneous());
    nearest = std::max(nearest, std::abs(w));
    farthest = std::min(farthest, std::abs(w));
    if (w * inverse_depth.dot(corners[0].homogeneous()) <= 0) return 0.0;  // a corner behind
  }
  return nearest / farthest;
}

// Whether the first side (corner 0 to 1) and its opposite are the long ones. In an oblique view,
// the assignment for which the implied camera is one (a focal length between kMinFocal and
// kMaxFocal image widths from each constraint that gives one, the two within kFocalAgreement of
// each other), when only one of the two is. Otherwise, and in an overhead view (which leaves the
// constraints 0 / 0), the longer pair in the image.
bool LongSideFirst(const std::array<Eigen::Vector2d, 4>& corners, const cv::Size& size) {
  const double first = (corners[1] - corners[0]).norm() + (corners[2] - corners[3]).norm();
  const double second = (corners[2] - corners[1]).norm() + (corners[3] - corners[0]).norm();
  if (DepthRatio(corners) <= kOverheadDepthRatio) return first >= second;
  bool camera[2];
  for (const bool long_first : {true, false}) {
    const auto [f1, f2] = FocalLengthsSquared(ImageFromTable(corners, long_first), size);
    std::vector<double> focal;  // [image widths]
    for (const double f : {f1, f2}) {
      if (f > 0 && std::isfinite(f)) focal.push_back(std::sqrt(f) / size.width);
    }
    bool plausible = !focal.empty();
    for (const double f : focal) plausible = plausible && f >= kMinFocal && f <= kMaxFocal;
    if (focal.size() == 2) {
      plausible = plausible && std::abs(std::log(focal[0] / focal[1])) < std::log(kFocalAgreement);
    }
    camera[long_first ? 0 : 1] = plausible;
  }
  return camera[0] != camera[1] ? camera[0] : first >= second;
}

// The long side over the short side of the rectangle whose image, seen from overhead, is the
// quadrilateral `corners` (in order around it): the ratio of the lines through the midpoints of
// opposite sides, which the small perspective of an overhead view leaves nearly as on the table.
// (An oblique view's ratio needs the camera's focal length, which the vanishing points give only
// where both pairs of sides converge and the principal point is known (Zhang and He 2007): a
// broadcast frame is cropped, a view straight along the table has one vanishing point; so an
// oblique view is not judged by its ratio.)
double OverheadAspect(const std::array<Eigen::Vector2d, 4>& corners) {
  const double along = (0.5 * (corners[1] + corners[2]) - 0.5 * (corners[0] + corners[3])).norm();
  const double across = (0.5 * (corners[2] + corners[3]) - 0.5 * (corners[0] + corners[1])).norm();
  return std::max(along, across) / std::min(along, across);
}

// The cloth's outline along side `side` at full resolution (ClothSide) near the first of the side's
// straight stretches at the search resolution (`stretches`, best supported first; the other sides
// as in `rough_lines`) that a straight edge along both halves of the side confirms, and which
// stretch that was; none when no stretch is.
struct ClothEdge {
  EdgeLine edge;
  std::size_t stretch = 0;
};
std::optional<ClothEdge> ClothSideOfStretches(const cv::Mat& bgr,
                                              std::array<Eigen::Vector3d, 4> rough_lines,
                                              const std::vector<Line>& stretches, bool long_first,
                                              int side, double search_px) {
  for (std::size_t k = 0; k < stretches.size(); ++k) {
    rough_lines[side] = stretches[k].coefficients;
    std::array<Eigen::Vector2d, 4> corners;
    if (!Intersections(rough_lines, &corners)) continue;
    const auto found =
        ClothSide(bgr, ImageFromTable(corners, long_first), long_first, side, search_px);
    if (found) return ClothEdge{*found, k};
  }
  return std::nullopt;
}

// The lines of the cushions' noses inside the cloth's outline `cloth_corners` (the outline's own
// side where none is found), and whether each was found along the side (`along`): met at
// kOtherStretchNose of the places along it at least, or the faint line of a cushion seen from
// behind (whose median change of colour stands out on both halves of the side).
std::array<Eigen::Vector3d, 4> CushionNoses(const cv::Mat& bgr,
                                            const std::array<Eigen::Vector2d, 4>& cloth_corners,
                                            bool long_first, std::array<bool, 4>* along) {
  const Eigen::Matrix3d cloth_from_table = ImageFromTable(cloth_corners, long_first);
  // The side nearest the camera (the largest inverse depth at its middle), whose cushion is seen
  // from behind in an oblique view.
  const Eigen::Vector3d cloth_depth = cloth_from_table.inverse().row(2).transpose();
  int nearest = 0;
  double nearest_inverse_depth = 0;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d middle = 0.5 * (cloth_corners[i] + cloth_corners[(i + 1) % 4]);
    const double w = std::abs(cloth_depth.dot(middle.homogeneous()));
    if (w > nearest_inverse_depth) {
      nearest_inverse_depth = w;
      nearest = i;
    }
  }
  const bool oblique = DepthRatio(cloth_corners) > kOverheadDepthRatio;
  const Eigen::Vector2d centre = 0.25 * (cloth_corners[0] + cloth_corners[1] + cloth_corners[2] +
                                         cloth_corners[3]);
  std::array<Eigen::Vector3d, 4> lines;
  for (int i = 0; i < 4; ++i) {
    const std::optional<EdgeLine> edge =
        NoseLine(bgr, cloth_from_table, long_first, i, kMaxCushionWidth);
    (*along)[i] = edge && edge->places >= kOtherStretchNose * kEdgePlaces;
    std::optional<Eigen::Vector3d> nose;
    if (edge) nose = edge->line;
    if (oblique && i == nearest) {
      // Seen from behind, the cushion's top is of the cloth, and a straight edge met along the
      // band is its back or the rail's, outside its faint nose.
      const auto faint = FaintNoseLine(bgr, cloth_from_table, long_first, i, kMaxCushionWidth);
      const Eigen::Vector2d middle = 0.5 * (cloth_corners[i] + cloth_corners[(i + 1) % 4]);
      const auto inward = [&](const Eigen::Vector3d& line) {
        return -line.dot(middle.homogeneous()) / line.head<2>().dot(centre - middle);
      };
      if (faint && (!nose || inward(*faint) > inward(*nose))) {
        nose = faint;
        (*along)[i] = true;
      }
    }
    lines[i] = nose.value_or(SideLine(cloth_from_table, long_first, i));
  }
  return lines;
}

// The lens the cloth's outline implies (lens_estimate.h): its points along the middle of each side
// of the hull's quadrilateral `polygon` [search px, at `scale` of the frame's].
RadialLens OutlineLens(const std::vector<cv::Point>& outline, const std::vector<cv::Point>& polygon,
                       double perimeter, double scale, const cv::Size& size) {
  std::array<std::vector<Eigen::Vector2d>, 4> sides;
  for (int i = 0; i < 4; ++i) {
    for (const auto& p : SidePoints(outline, polygon[i], polygon[(i + 1) % 4], perimeter)) {
      sides[i].emplace_back(p.x / scale, p.y / scale);
    }
  }
  return EstimateRadialLens(sides, size, 1.0 / scale).lens;
}

// The side of the found table that is the frame's border, where part of it is out of the frame
// (table_partial.h): one side of its cloth along the border.
std::optional<int> SideOutOfFrame(const TableRegion& table, const cv::Size& size,
                                  double border_px) {
  const std::vector<int> along = SidesAlongBorder(table.cloth_corners, size, border_px);
  if (along.size() != 1) return std::nullopt;
  return along.front();
}

// The table with its side `cut` beyond the frame's border: the playing surface and the cloth's
// outline completed to a table's proportions, the cloth's unseen side as far beyond the surface's
// as the seen opposite one is. Left as found where the completion is not a table seen from
// overhead, the one view the completion holds for (an oblique view's near side cut by the frame
// is a side of the table seen whole, as far as the homography is concerned).
void CompleteAcrossBorder(int cut, TableRegion* table) {
  const auto corners = CompletedAcrossBorder(table->corners, cut, kTableAspect);
  if (!corners || DepthRatio(*corners) > kOverheadDepthRatio) return;
  const int end_a = (cut + 2) % 4, end_b = (cut + 3) % 4;
  for (const auto& [border, end] : {std::pair{(cut + 1) % 4, end_a}, std::pair{cut, end_b}}) {
    const Eigen::Vector2d along = ((*corners)[border] - table->corners[end]).normalized();
    const double cushion = (table->corners[end] - table->cloth_corners[end]).dot(along);
    table->cloth_corners[border] = (*corners)[border] + cushion * along;
  }
  table->corners = *corners;
  table->side_out_of_frame = cut;
}

TableSearch Placed(TableRegion table, bool long_first, const TableRegion& cloth);

TableSearch FindTable(const cv::Mat& bgr, bool estimate_lens);

// The table found in the frame redrawn as `lens`'s pinhole sees it, given in the frame: its
// corners through the lens, its masks the frame's `cloth`'s, its geometry the pinhole's.
TableSearch FindThroughLens(const cv::Mat& bgr, const RadialLens& lens, const TableRegion& cloth) {
  const TableSearch pinhole = FindTable(lens.Undistort(bgr), false);
  if (!pinhole.table) {
    char k1[32];
    std::snprintf(k1, sizeof k1, "%.3f", lens.k1);
    return {std::nullopt, pinhole.reason + " (through the lens found, k1 = " + k1 + ")", cloth};
  }
  TableRegion table = *pinhole.table;
  for (int i = 0; i < 4; ++i) {
    table.corners[i] = lens.ToImage(table.corners[i]);
    table.cloth_corners[i] = lens.ToImage(table.cloth_corners[i]);
  }
  table.lens = lens;
  table.cloth = cloth.cloth;
  table.surface = cloth.surface;
  table.mask_scale = cloth.mask_scale;
  return {table, "", std::nullopt};
}

// The cloth's sides and the cushions' noses inside them (the lines of the playing surface) from
// the straight stretches of its outline at the search resolution (`stretches`, best supported
// first, at `scale` of the frame's), each side confirmed at full resolution; `table`'s
// cloth_corners and side_fit_rms_px set. False when two neighbouring sides do not meet.
bool SidesAndNoses(const cv::Mat& bgr, const std::array<std::vector<Line>, 4>& stretches,
                   double scale, bool long_first, TableRegion* table,
                   std::array<Eigen::Vector3d, 4>* lines) {
  std::array<Eigen::Vector3d, 4> rough_lines;
  for (int i = 0; i < 4; ++i) rough_lines[i] = stretches[i].front().coefficients;
  // A stretch of a side's outline other than its best supported is the cloth's side only when the
  // cushion's nose found inside it runs along the side too (CushionNoses): the stretch a straight
  // edge confirms may be the rail's, beyond a cushion whose nose cannot be seen (or is hidden by
  // whoever hid the first stretch), and the side would be left at the rail. A cushion seen from
  // behind has its outline there (its top is of the cloth), and its faint nose confirms it.
  std::array<bool, 4> other_stretches = {true, true, true, true};
  for (bool again = true; again;) {
    again = false;
    std::array<bool, 4> other_stretch_taken = {false, false, false, false};
    double squares = 0;
    int points = 0;
    for (int i = 0; i < 4; ++i) {
      // Where no straight edge is near it, the side found at the search resolution stands.
      const Line& best = stretches[i].front();
      const std::vector<Line> tried(
          stretches[i].begin(), other_stretches[i] ? stretches[i].end() : stretches[i].begin() + 1);
      const std::optional<ClothEdge> found =
          ClothSideOfStretches(bgr, rough_lines, tried, long_first, i, kOutlineSearchPx / scale);
      const EdgeLine side = found ? found->edge : EdgeLine{best.coefficients, best.points, 0.0, best.rms};
      other_stretch_taken[i] = found && found->stretch > 0;
      (*lines)[i] = side.line;
      squares += side.rms_px * side.rms_px * side.places;
      points += side.places;
    }
    table->side_fit_rms_px = std::sqrt(squares / std::max(1, points));
    if (!Intersections(*lines, &table->cloth_corners)) return false;
    std::array<bool, 4> nose_along;
    *lines = CushionNoses(bgr, table->cloth_corners, long_first, &nose_along);
    for (int i = 0; i < 4; ++i) {
      if (other_stretch_taken[i] && !nose_along[i]) {
        other_stretches[i] = false;
        again = true;
      }
    }
  }
  return true;
}

// The region of `colour` in `small` (the frame reduced by `scale`); none below kMinClothFraction.
std::optional<TableRegion> ClothOfColour(const cv::Mat& small, double scale,
                                         const cv::Vec3f& colour) {
  TableRegion cloth;
  cloth.mask_scale = scale;
  cloth.cloth_colour = colour;
  cloth.cloth = LargestCentralRegion(ClothLike(small, colour));
  if (cv::countNonZero(cloth.cloth) < kMinClothFraction * small.total()) return std::nullopt;
  cloth.surface = FillHoles(cloth.cloth);
  return cloth;
}

// The table whose cloth is of the colour `cloth_colour` in the frame (`small`, its reduction by
// `scale`); its lens estimated first when `estimate_lens`. `quadrilateral` tells whether the
// colour's region is a quadrilateral with straight sides (or sides a lens bends), the table found
// or not: a cloth, not what lies around one.
TableSearch FindTableOfCloth(const cv::Mat& bgr, const cv::Mat& small, double scale,
                             const cv::Vec3f& cloth_colour, bool estimate_lens,
                             bool* quadrilateral) {
  *quadrilateral = false;
  const std::optional<TableRegion> found = ClothOfColour(small, scale, cloth_colour);
  if (!found) {
    const std::string share = std::to_string(static_cast<int>(100 * kMinClothFraction));
    return {std::nullopt, "no table: no evenly coloured cloth covers " + share + " % of the frame",
            std::nullopt};
  }
  // Past here the cloth is found: a frame without its table still has it (TableSearch::cloth).
  const TableRegion& cloth = *found;
  TableRegion table = cloth;

  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(table.surface.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  const auto& outline =
      *std::max_element(contours.begin(), contours.end(),
                        [](const auto& a, const auto& b) { return a.size() < b.size(); });
  std::vector<cv::Point> hull, polygon;
  cv::convexHull(outline, hull);
  const double perimeter = cv::arcLength(hull, true);
  for (double tolerance = kFirstPolygonTolerance; tolerance < kLastPolygonTolerance;
       tolerance += kPolygonToleranceStep) {
    cv::approxPolyDP(hull, polygon, tolerance * perimeter, true);
    if (polygon.size() <= 4) break;
  }
  if (polygon.size() != 4) {
    return {std::nullopt, "no table: the cloth's outline is not a quadrilateral", cloth};
  }
  if (estimate_lens) {
    const RadialLens lens = OutlineLens(outline, polygon, perimeter, scale, bgr.size());
    *quadrilateral = !lens.IsPinhole();
    if (*quadrilateral) return FindThroughLens(bgr, lens, cloth);
  }
  std::array<std::vector<Line>, 4> stretches;
  std::array<Eigen::Vector3d, 4> lines;
  for (int i = 0; i < 4; ++i) {
    stretches[i] = FitSides(outline, polygon[i], polygon[(i + 1) % 4], perimeter);
    if (stretches[i].empty()) {
      return {std::nullopt, "no table: a side of the cloth is not straight", cloth};
    }
    for (Line& stretch : stretches[i]) {
      stretch.coefficients.z() /= scale;  // to full-resolution pixels
      stretch.rms /= scale;
    }
    lines[i] = stretches[i].front().coefficients;
  }
  *quadrilateral = true;
  if (!Intersections(lines, &table.cloth_corners)) {
    return {std::nullopt, "no table: two neighbouring sides of the cloth do not meet", cloth};
  }
  const bool long_first = LongSideFirst(table.cloth_corners, bgr.size());
  if (!SidesAndNoses(bgr, stretches, scale, long_first, &table, &lines)) {
    return {std::nullopt, "no table: two neighbouring sides of the cloth do not meet", cloth};
  }
  if (!Intersections(lines, &table.corners)) {
    return {std::nullopt, "no table: two neighbouring cushions do not meet", cloth};
  }
  if (const auto cut = SideOutOfFrame(table, bgr.size(), kFrameEdgePx / scale)) {
    CompleteAcrossBorder(*cut, &table);
  }
  // A completed table is seen from overhead: its long sides are the long ones in the frame.
  const bool long_side_first =
      table.side_out_of_frame >= 0 ? LongSideFirst(table.corners, bgr.size()) : long_first;
  return Placed(std::move(table), long_side_first, cloth);
}

// The table of `corners` and `cloth_corners` found, placed: its homography, depth and view; none
// where its corners are not a plane's in view, or, seen from overhead, it is not a table's shape.
TableSearch Placed(TableRegion table, bool long_first, const TableRegion& cloth) {
  table.image_from_table = ImageFromTable(table.corners, long_first);
  const Eigen::Vector3d inverse_depth = table.image_from_table.inverse().row(2).transpose();
  table.inverse_depth = inverse_depth / inverse_depth.dot(table.Centre().homogeneous());
  table.depth_ratio = DepthRatio(table.corners);
  if (!(table.depth_ratio > 0)) {
    return {std::nullopt, "no table: the cloth's corners are not those of a plane in view", cloth};
  }
  table.view =
      table.depth_ratio <= kOverheadDepthRatio ? TableView::kOverhead : TableView::kOblique;
  const double aspect = OverheadAspect(table.corners);
  if (table.view == TableView::kOverhead &&
      std::abs(std::log(aspect / kTableAspect)) > std::log(kOverheadAspectTolerance)) {
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%.2f", aspect);
    return {std::nullopt, std::string("no table: the surface found is ") + ratio +
                              " times as long as it is wide, not a table's 2", cloth};
  }
  return {table, "", std::nullopt};
}

// Whether a colour is white, not a cloth's (a chart, a sheet of paper).
bool IsWhite(const cv::Vec3f& bgr) {
  const cv::Vec3f lab = LabOfBgr(bgr);
  return lab[0] > kMaxClothLightness && std::hypot(lab[1], lab[2]) < kMinClothChroma;
}

// A search that found no table, given the regions of the frame's other colours than its first
// (TableSearch::other_cloths): the ball detector's fallback chooses the cloth among them.
TableSearch WithOtherCloths(TableSearch search, const cv::Mat& small, double scale,
                            const std::vector<cv::Vec3f>& colours) {
  for (std::size_t k = 1; k < colours.size(); ++k) {
    if (IsWhite(colours[k])) continue;
    if (auto other = ClothOfColour(small, scale, colours[k])) search.other_cloths.push_back(*other);
  }
  return search;
}

// The table in the frame; its lens estimated first when `estimate_lens` (not in a frame redrawn
// through the lens already). The cloth is the frame's likeliest colour (ClothColours); where its
// region is no plane's quadrilateral with straight sides (the wall or floor around a table seen
// from a low camera, whose outline follows the table's far rail and its sides), the next colours
// are tried, and the first that makes a table is the cloth: a table whole in the frame, since the
// first colour was around it (a side along the frame's edge is the floor's, around a cloth that
// is no table: a round mat). Where the first colour's region is a quadrilateral with straight
// sides, it is the cloth, its table found or not (an end out of the frame, an arm across a
// corner): no other colour's table is tried. No table found, the others' regions go beside it.
TableSearch FindTable(const cv::Mat& bgr, bool estimate_lens) {
  if (bgr.empty() || bgr.type() != CV_8UC3) return {std::nullopt, "not a BGR colour frame", std::nullopt};
  const double scale = 1.0 / SearchReduction(bgr.size());
  cv::Mat small;
  cv::resize(bgr, small, {}, scale, scale, cv::INTER_AREA);
  const std::vector<cv::Vec3f> colours = ClothColours(small, kClothColours);
  if (IsWhite(colours.front())) {
    return {std::nullopt, "no table: what fills the frame's middle is white, not a cloth",
            std::nullopt};
  }
  TableSearch first;
  for (std::size_t k = 0; k < colours.size(); ++k) {
    if (k > 0 && IsWhite(colours[k])) continue;
    bool quadrilateral = false;
    TableSearch search =
        FindTableOfCloth(bgr, small, scale, colours[k], estimate_lens, &quadrilateral);
    if (k > 0 && search.table && CutByFrame(*search.table, bgr.size())) continue;
    if (search.table) return search;
    if (k == 0 && quadrilateral) return WithOtherCloths(std::move(search), small, scale, colours);
    if (k == 0) first = std::move(search);
  }
  return WithOtherCloths(std::move(first), small, scale, colours);
}

}  // namespace

TableSearch FindTable(const cv::Mat& bgr) { return FindTable(bgr, true); }

}  // namespace billiard::estimator
