#include "bench/frame_score.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <tuple>

namespace billiard::bench {

namespace {

// A detection matches within max(kMinMatchPx, kMatchRadii R) of its label.
constexpr double kMinMatchPx = 8.0, kMatchRadii = 0.6;
// ExplainMisses' neighbourhoods, in ball radii.
constexpr double kCushionRadii = 1.5, kClusterRadii = 2.5, kDuplicateRadii = 2.0;

// The segment from `a` to `b` within the frame `size` (Liang and Barsky 1984); false when none
// of it is.
bool ClipToFrame(const cv::Size& size, Eigen::Vector2d* a, Eigen::Vector2d* b) {
  double t0 = 0, t1 = 1;
  const Eigen::Vector2d d = *b - *a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a->x(), size.width - 1 - a->x(), a->y(), size.height - 1 - a->y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
  }
  if (t0 > t1) return false;
  const Eigen::Vector2d start = *a;
  *a = start + t0 * d;
  *b = start + t1 * d;
  return true;
}

double DistanceToLine(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = (b - a).normalized();
  return std::abs(d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x()));
}

bool InsideLabelledTable(const std::array<Eigen::Vector2d, 4>& corners, const Eigen::Vector2d& p) {
  std::vector<cv::Point2f> polygon;
  for (const auto& c : corners) {
    polygon.emplace_back(static_cast<float>(c.x()), static_cast<float>(c.y()));
  }
  return cv::pointPolygonTest(polygon, cv::Point2f(static_cast<float>(p.x()),
                                                   static_cast<float>(p.y())),
                              false) >= 0;
}

}  // namespace

void ExplainMisses(const LabelledFrame& frame, FrameScore* score) {
  const double r = frame.radius_px;
  score->missed_causes.clear();
  for (const Eigen::Vector2d& p : score->missed) {
    std::string cause = "on open cloth";
    bool by_cushion = false;
    if (frame.corners) {
      for (int side = 0; side < 4; ++side) {
        by_cushion = by_cushion || DistanceToLine(p, (*frame.corners)[side],
                                                  (*frame.corners)[(side + 1) % 4]) <
                                       kCushionRadii * r;
      }
    }
    const bool clustered = std::any_of(frame.balls.begin(), frame.balls.end(), [&](const auto& q) {
      return q != p && (q - p).norm() < kClusterRadii * r;
    });
    if (!score->table) {
      cause = "no table";
    } else if (!score->table->Contains(p)) {
      cause = "outside the table found";
    } else if (by_cushion) {
      cause = "by the cushion";
    } else if (clustered) {
      cause = "in a cluster";
    }
    score->missed_causes.push_back(cause);
  }
  score->false_causes.clear();
  for (std::size_t i = 0; i < score->detections.size(); ++i) {
    if (score->detection_matched[i]) continue;
    const Eigen::Vector2d& p = score->detections[i].pixel;
    bool duplicate = false;
    for (std::size_t j = 0; j < score->detections.size(); ++j) {
      duplicate = duplicate || (score->detection_label[j] >= 0 &&
                                (frame.balls[score->detection_label[j]] - p).norm() <
                                    kDuplicateRadii * r);
    }
    if (duplicate) {
      score->false_causes.push_back("duplicate");
    } else if (frame.corners && !InsideLabelledTable(*frame.corners, p)) {
      score->false_causes.push_back("off the table");
    } else {
      score->false_causes.push_back("on the table");
    }
  }
}

double MatchDistancePx(double radius_px) { return std::max(kMinMatchPx, kMatchRadii * radius_px); }

FrameScore ScoreFrame(const LabelledFrame& frame,
                      const std::vector<estimator::BallDetection>& detections) {
  FrameScore score;
  score.file = frame.file;
  score.source = frame.source;
  score.labels = static_cast<int>(frame.balls.size());
  score.detections = detections;
  score.detection_matched.assign(detections.size(), false);
  score.detection_label.assign(detections.size(), -1);
  const double gate = MatchDistancePx(frame.radius_px);
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < detections.size(); ++i) {
    for (std::size_t j = 0; j < frame.balls.size(); ++j) {
      const double d = (detections[i].pixel - frame.balls[j]).norm();
      if (d < gate) pairs.emplace_back(d, i, j);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> label_matched(frame.balls.size(), false);
  for (const auto& [d, i, j] : pairs) {
    if (score.detection_matched[i] || label_matched[j]) continue;
    score.detection_matched[i] = label_matched[j] = true;
    score.detection_label[i] = static_cast<int>(j);
    score.centre_errors.push_back(d);
    if (j < frame.classes.size() && !frame.classes[j].empty()) {
      ++score.classed;
      score.classed_right += ClassMatches(frame.classes[j], detections[i].ball_class);
    }
  }
  score.found = static_cast<int>(score.centre_errors.size());
  for (std::size_t j = 0; j < frame.balls.size(); ++j) {
    if (!label_matched[j]) score.missed.push_back(frame.balls[j]);
  }
  for (std::size_t i = 0; i < detections.size(); ++i) {
    if (score.detection_matched[i]) continue;
    const bool ignored =
        std::any_of(frame.ignored.begin(), frame.ignored.end(),
                    [&](const auto& p) { return (detections[i].pixel - p).norm() < gate; });
    if (ignored) {
      score.detection_matched[i] = true;
    } else {
      ++score.false_detections;
    }
  }
  return score;
}

double TableSideError(const LabelledFrame& frame, const estimator::TableRegion& table,
                      const cv::Size& size) {
  const auto& label = *frame.corners;
  std::array<Eigen::Vector2d, 4> found{};
  double best = HUGE_VAL;
  for (int turn = 0; turn < 4; ++turn) {
    for (const int direction : {1, -1}) {
      std::array<Eigen::Vector2d, 4> candidate;
      double sum = 0;
      for (int i = 0; i < 4; ++i) {
        candidate[i] = table.corners[((turn + direction * i) % 4 + 4) % 4];
        sum += (candidate[i] - label[i]).norm();
      }
      if (sum < best) {
        best = sum;
        found = candidate;
      }
    }
  }
  double error = 0;
  for (int side = 0; side < 4; ++side) {
    if (side == frame.unseen_side) continue;
    Eigen::Vector2d a = label[side], b = label[(side + 1) % 4];
    if (!ClipToFrame(size, &a, &b)) continue;
    for (const Eigen::Vector2d& end : {a, b}) {
      error = std::max(error, DistanceToLine(end, found[side], found[(side + 1) % 4]));
    }
  }
  return error;
}

}  // namespace billiard::bench
