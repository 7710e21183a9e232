#include "estimator/table_edges.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

namespace billiard::estimator {

namespace {

// The edges are looked for at kEdgeSamples places on each half of a side, from kEdgeFrom of its
// length from a corner to kEdgeMiddle from its middle (the pockets are at both); an edge is a
// colour change of at least kMinEdge L*a*b* units per pixel and kEdgeNoises times the median
// over the band searched (the cloth's weave and the camera's noise). Up to kMaxLines lines are
// found, each through the edges of at least kMinPlaces of the places on each half of the side;
// RANSAC (kEdgeRansacTries tries) keeps the edges within kEdgeInlierPx of a line.
constexpr int kEdgeSamples = kEdgePlaces / 2;
constexpr double kEdgeFrom = 0.12, kEdgeMiddle = 0.08;
constexpr double kMinEdge = 2.0, kEdgeNoises = 4.0;
constexpr int kMaxLines = 3;
constexpr double kMinPlaces = 0.3;
constexpr double kEdgeInlierPx = 1.5;
constexpr int kEdgeRansacTries = 200;
// The cloth against the rail is no nose: the noses are looked for from kOutlineClearancePx inside
// the outline. Of the lines there, the nose is the best supported, or the innermost of those
// nearly as well (kNoseOfBest of its places): an old cloth's worn track along the cushion is a
// line too, fainter, and more broken.
constexpr int kOutlineClearancePx = 3;
constexpr double kNoseOfBest = 0.95;
// FaintNoseLine: the median rate of change along a line must be kFaintEdges times the band's
// median on both halves of the side, and kMinFaintEdge L*a*b* units per pixel (half of kMinEdge,
// which a single place's edge must pass), and more than along the lines
// kFaintRidge steps either side (a ridge, not the blur of the outline's edge); lines within
// kFaintClearancePx more of the outline are not looked at, nor lines turned more than
// kFaintMaxTilt of the band across the side.
constexpr double kFaintEdges = 2.0, kMinFaintEdge = 1.0;
constexpr int kFaintRidge = 2;
constexpr int kFaintClearancePx = 3;
constexpr double kFaintMaxTilt = 0.25;

// Bilinear BGR colours of a frame at `points` [px] in float L*a*b*; points outside the frame get
// NaN. Not LabImage's 8-bit L*a*b*: its steps move the cushions' edges enough to cost balls near
// them (3 more false detections and 3 fewer balls on the dev frames).
std::vector<cv::Vec3f> LabAt(const cv::Mat& bgr, const std::vector<Eigen::Vector2d>& points) {
  cv::Mat samples(static_cast<int>(points.size()), 1, CV_32FC3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double x = points[i].x(), y = points[i].y();
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    if (x0 < 0 || y0 < 0 || x0 + 1 >= bgr.cols || y0 + 1 >= bgr.rows) {
      samples.at<cv::Vec3f>(static_cast<int>(i)) = cv::Vec3f(NAN, NAN, NAN);
      continue;
    }
    const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
    const auto at = [&](int yy, int xx) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(yy, xx);
      return cv::Vec3f(p[0], p[1], p[2]) / 255.0f;
    };
    samples.at<cv::Vec3f>(static_cast<int>(i)) =
        (1 - fy) * ((1 - fx) * at(y0, x0) + fx * at(y0, x0 + 1)) +
        fy * ((1 - fx) * at(y0 + 1, x0) + fx * at(y0 + 1, x0 + 1));
  }
  cv::Mat lab;
  cv::cvtColor(samples, lab, cv::COLOR_BGR2Lab);
  return std::vector<cv::Vec3f>(lab.begin<cv::Vec3f>(), lab.end<cv::Vec3f>());
}

}  // namespace

std::array<Eigen::Vector2d, 4> TableCorners(bool long_first) {
  const double a = kTableAspect;
  return long_first ? std::array<Eigen::Vector2d, 4>{{{0, 0}, {a, 0}, {a, 1}, {0, 1}}}
                    : std::array<Eigen::Vector2d, 4>{{{0, 0}, {0, 1}, {a, 1}, {a, 0}}};
}
Eigen::Vector3d SideLine(const Eigen::Matrix3d& image_from_table, bool long_first, int side) {
  const auto table = TableCorners(long_first);
  return (image_from_table * table[side].homogeneous())
      .cross(image_from_table * table[(side + 1) % 4].homogeneous());
}

namespace {

// The colour's rate of change going inward across a side, at places along it: `rate` holds
// `offsets` values a place, a step inward each (about a pixel where the side is nearest), from
// `from` table widths inward; `points` the image points of the samples (offsets + 1 a place).
struct SideProfiles {
  std::vector<double> along;  // place k at this fraction of the side
  std::vector<Eigen::Vector2d> points;
  std::vector<double> rate;
  int offsets = 0;
  Eigen::Vector3d side_line;  // the side's own line, (a, b) unit
  double towards_centre = 1;  // the sign of side_line towards the table's centre
};

SideProfiles Profiles(const cv::Mat& bgr, const Eigen::Matrix3d& image_from_table,
                      bool long_first, int side, double from, double to) {
  SideProfiles profiles;
  const auto table = TableCorners(long_first);
  const Eigen::Vector2d a = table[side], b = table[(side + 1) % 4];
  const Eigen::Vector2d centre(0.5 * kTableAspect, 0.5);
  Eigen::Vector2d inward(-(b - a).y(), (b - a).x());
  inward.normalize();
  if (inward.dot(centre - a) < 0) inward = -inward;
  const auto image = [&](double t, double u) {
    return (image_from_table * (a + t * (b - a) + u * inward).homogeneous()).hnormalized();
  };
  Eigen::Vector3d side_line = image(0, 0).homogeneous().cross(image(1, 0).homogeneous());
  side_line /= side_line.head<2>().norm();
  const double towards_centre = side_line.dot(image(0.5, 0.1).homogeneous()) > 0 ? 1.0 : -1.0;
  // Offsets a pixel apart where the side is nearest the camera (the largest scale along it).
  double px_per_unit = 0;
  for (const double t : {0.0, 0.5, 1.0}) {
    px_per_unit = std::max(px_per_unit, (image(t, 0.01) - image(t, 0)).norm() / 0.01);
  }
  // Never more offsets than the frame's diagonal has pixels: a quadrilateral with a corner near its
  // horizon would ask for millions.
  const double max_px_per_unit = std::hypot(bgr.cols, bgr.rows) / std::max(to - from, 1e-6);
  const double step = 1.0 / std::min(std::max(1.0, px_per_unit), max_px_per_unit);
  const int offsets = static_cast<int>((to - from) / step) + 1;
  std::vector<double> along;
  for (int k = 0; k < kEdgeSamples; ++k) {
    const double t = kEdgeFrom + (k + 0.5) * (0.5 - kEdgeFrom - kEdgeMiddle) / kEdgeSamples;
    along.push_back(t);
    along.push_back(1.0 - t);
  }
  std::vector<Eigen::Vector2d> points;
  for (const double t : along) {
    for (int i = 0; i <= offsets; ++i) points.push_back(image(t, from + i * step));
  }
  const std::vector<cv::Vec3f> lab = LabAt(bgr, points);
  // The colour's rate of change inward at each place and offset.
  std::vector<double> rate(along.size() * offsets);
  for (std::size_t k = 0; k < along.size(); ++k) {
    const std::size_t base = k * (offsets + 1);
    for (int i = 0; i < offsets; ++i) {
      const cv::Vec3f d = lab[base + i + 1] - lab[base + i];
      const double pixels = (points[base + i + 1] - points[base + i]).norm();
      const double r = std::sqrt(d.dot(d)) / std::max(pixels, 1e-6);
      rate[k * offsets + i] = std::isfinite(r) ? r : 0.0;
    }
  }
  profiles.along = along;
  profiles.points = points;
  profiles.rate = rate;
  profiles.offsets = offsets;
  profiles.side_line = side_line;
  profiles.towards_centre = towards_centre;
  return profiles;
}

double MedianOf(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

}  // namespace

std::vector<EdgeLine> EdgeLinesAlong(const cv::Mat& bgr, const Eigen::Matrix3d& image_from_table,
                                     bool long_first, int side, double from, double to,
                                     double clearance_px) {
  const SideProfiles profiles = Profiles(bgr, image_from_table, long_first, side, from, to);
  const auto& along = profiles.along;
  const auto& points = profiles.points;
  const auto& rate = profiles.rate;
  const int offsets = profiles.offsets;
  const auto& side_line = profiles.side_line;
  const double towards_centre = profiles.towards_centre;
  const double min_edge = std::max(kMinEdge, kEdgeNoises * MedianOf(rate));
  // The edges along each place, to a fraction of a sample (the parabola through the maximum and
  // its neighbours): (image point, place).
  std::vector<std::pair<Eigen::Vector2d, int>> edges;
  for (std::size_t k = 0; k < along.size(); ++k) {
    const std::size_t base = k * (offsets + 1);
    const double* r = &rate[k * offsets];
    for (int i = 1; i + 1 < offsets; ++i) {
      if (r[i] < min_edge || r[i] < r[i - 1] || r[i] <= r[i + 1]) continue;
      const double curvature = r[i - 1] - 2 * r[i] + r[i + 1];
      const double offset =
          curvature < 0 ? std::clamp(0.5 * (r[i - 1] - r[i + 1]) / curvature, -1.0, 1.0) : 0.0;
      const Eigen::Vector2d middle = 0.5 * (points[base + i] + points[base + i + 1]);
      const Eigen::Vector2d next = 0.5 * (points[base + i + 1] + points[base + i + 2]);
      const Eigen::Vector2d edge = middle + offset * (next - middle);
      if (std::abs(side_line.dot(edge.homogeneous())) < clearance_px) continue;
      edges.push_back({edge, static_cast<int>(k)});
    }
  }
  std::vector<EdgeLine> lines;
  std::vector<bool> taken(edges.size(), false);
  std::mt19937 random(side + 1);
  for (int found = 0; found < kMaxLines && edges.size() >= 2; ++found) {
    std::uniform_int_distribution<std::size_t> pick(0, edges.size() - 1);
    int best_places = 0;
    std::vector<std::size_t> best_inliers;
    for (int attempt = 0; attempt < kEdgeRansacTries; ++attempt) {
      const std::size_t i = pick(random), j = pick(random);
      if (taken[i] || taken[j] || edges[i].second == edges[j].second) continue;
      Eigen::Vector3d line = edges[i].first.homogeneous().cross(edges[j].first.homogeneous());
      line /= line.head<2>().norm();
      std::vector<bool> place_seen(along.size(), false);
      std::vector<std::size_t> inliers;
      for (std::size_t e = 0; e < edges.size(); ++e) {
        if (taken[e] || std::abs(line.dot(edges[e].first.homogeneous())) > kEdgeInlierPx) continue;
        inliers.push_back(e);
        place_seen[edges[e].second] = true;
      }
      // Places alternate between the side's halves: a cushion runs along both, a row of balls
      // against it along one at most.
      int halves[2] = {0, 0};
      for (std::size_t k = 0; k < along.size(); ++k) halves[k % 2] += place_seen[k];
      const int places = 2 * std::min(halves[0], halves[1]);
      if (places > best_places) {
        best_places = places;
        best_inliers = inliers;
      }
    }
    if (best_places < kMinPlaces * static_cast<double>(along.size())) break;
    std::vector<cv::Point2f> inlier_points;
    EdgeLine edge_line;
    edge_line.places = best_places;
    for (const std::size_t e : best_inliers) {
      taken[e] = true;
      inlier_points.emplace_back(static_cast<float>(edges[e].first.x()),
                                 static_cast<float>(edges[e].first.y()));
      edge_line.inward_px += towards_centre * side_line.dot(edges[e].first.homogeneous());
    }
    edge_line.inward_px /= best_inliers.size();
    cv::Vec4f fitted;
    cv::fitLine(inlier_points, fitted, cv::DIST_L2, 0, 0.01, 0.01);
    edge_line.line = {-fitted[1], fitted[0], fitted[1] * fitted[2] - fitted[0] * fitted[3]};
    double squares = 0;
    for (const auto& p : inlier_points) {
      squares += std::pow(edge_line.line.dot(Eigen::Vector3d(p.x, p.y, 1.0)), 2);
    }
    edge_line.rms_px = std::sqrt(squares / inlier_points.size());
    lines.push_back(edge_line);
  }
  return lines;
}

std::optional<EdgeLine> ClothSide(const cv::Mat& bgr, const Eigen::Matrix3d& image_from_table,
                                  bool long_first, int side, double search_px) {
  // The search's reach in table widths, where the side is farthest (foreshortened most).
  const auto table = TableCorners(long_first);
  const Eigen::Vector2d a = table[side], b = table[(side + 1) % 4];
  Eigen::Vector2d inward(-(b - a).y(), (b - a).x());
  inward.normalize();
  double px_per_unit = HUGE_VAL;
  for (const double t : {0.0, 0.5, 1.0}) {
    const Eigen::Vector2d p = a + t * (b - a);
    const auto image = [&](const Eigen::Vector2d& q) {
      return (image_from_table * q.homogeneous()).hnormalized();
    };
    px_per_unit = std::min(px_per_unit, (image(p + 0.01 * inward) - image(p)).norm() / 0.01);
  }
  const double reach = search_px / std::max(1e-9, px_per_unit);
  const auto lines = EdgeLinesAlong(bgr, image_from_table, long_first, side, -reach, reach, 0.0);
  if (lines.empty()) return std::nullopt;
  return lines.front();
}

std::optional<EdgeLine> NoseLine(const cv::Mat& bgr, const Eigen::Matrix3d& cloth_from_table,
                                 bool long_first, int side, double max_cushion_width) {
  const auto lines = EdgeLinesAlong(bgr, cloth_from_table, long_first, side, 0.0, max_cushion_width,
                                    kOutlineClearancePx);
  if (lines.empty()) return std::nullopt;
  const EdgeLine* nose = &lines.front();
  for (const EdgeLine& l : lines) {
    if (l.places >= kNoseOfBest * lines.front().places && l.inward_px > nose->inward_px) {
      nose = &l;
    }
  }
  return *nose;
}

std::optional<Eigen::Vector3d> FaintNoseLine(const cv::Mat& bgr,
                                             const Eigen::Matrix3d& cloth_from_table,
                                             bool long_first, int side,
                                             double max_cushion_width) {
  const SideProfiles profiles =
      Profiles(bgr, cloth_from_table, long_first, side, 0.0, max_cushion_width);
  const int n = profiles.offsets;
  if (n < 4) return std::nullopt;
  const double noise = MedianOf(profiles.rate);
  const auto& along = profiles.along;
  // The median rate along the line from offset i0 at the side's start to i1 at its end, per half
  // (places alternate between the halves), linearly between the samples: most places of a
  // cushion's line have its edge, where a few balls beside it are strong edges at few places.
  const auto median_rate = [&](double i0, double i1, int half) {
    std::vector<double> rates;
    for (std::size_t k = half; k < along.size(); k += 2) {
      const double i = i0 + (i1 - i0) * along[k];
      const int lower = static_cast<int>(std::floor(i));
      if (lower < 0 || lower + 1 >= n) continue;
      const double f = i - lower;
      rates.push_back((1 - f) * profiles.rate[k * n + lower] + f * profiles.rate[k * n + lower + 1]);
    }
    return rates.empty() ? 0.0 : MedianOf(rates);
  };
  const auto score_of = [&](double i0, double i1) {
    return std::min(median_rate(i0, i1, 0), median_rate(i0, i1, 1));
  };
  const int clearance = kOutlineClearancePx + kFaintClearancePx;
  const int max_tilt = static_cast<int>(kFaintMaxTilt * n);
  double best = 0, best_i0 = 0, best_i1 = 0;
  for (int i0 = clearance; i0 + 1 < n; ++i0) {
    for (int i1 = std::max(clearance, i0 - max_tilt); i1 + 1 < n && i1 <= i0 + max_tilt; ++i1) {
      const double score = score_of(i0, i1);
      // A ridge across the band, not the tail of a stronger edge's blur.
      const bool ridge = score > score_of(i0 - kFaintRidge, i1 - kFaintRidge) &&
                         score > score_of(i0 + kFaintRidge, i1 + kFaintRidge);
      if (ridge && score > best) {
        best = score;
        best_i0 = i0;
        best_i1 = i1;
      }
    }
  }
  if (best < std::max(kMinFaintEdge, kFaintEdges * noise)) return std::nullopt;
  // The line through the places' points at the best line's offsets (each between its samples,
  // where the rate of change between them is).
  std::vector<cv::Point2f> points;
  for (std::size_t k = 0; k < along.size(); ++k) {
    const double i = best_i0 + (best_i1 - best_i0) * along[k];
    const int lower = static_cast<int>(std::floor(i));
    if (lower < 0 || lower + 2 > n) continue;
    const double f = i - lower;
    const auto middle = [&](int j) {
      const std::size_t base = k * (n + 1);
      return 0.5 * (profiles.points[base + j] + profiles.points[base + j + 1]);
    };
    const Eigen::Vector2d p = (1 - f) * middle(lower) + f * middle(lower + 1);
    points.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
  }
  if (points.size() < 2) return std::nullopt;
  cv::Vec4f fitted;
  cv::fitLine(points, fitted, cv::DIST_L2, 0, 0.01, 0.01);
  return Eigen::Vector3d(-fitted[1], fitted[0], fitted[1] * fitted[2] - fitted[0] * fitted[3]);
}

}  // namespace billiard::estimator
