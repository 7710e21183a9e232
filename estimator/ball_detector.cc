#include "estimator/ball_detector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "estimator/ball_identity.h"
#include "estimator/ball_placement.h"
#include "estimator/ball_score.h"
#include "estimator/circle_votes.h"
#include "estimator/lab_image.h"
#include "estimator/table_fallback.h"

namespace billiard::estimator {

namespace {

// Peaks of the votes from kMinVoteSupport are outlined, strongest first, up to kMaxCandidates:
// every one (two peaks of one ball, one between the ball and its shadow, may give different
// outlines, and the better must win) but those within kExplainedRadii of an outline scoring
// kExplainedScore, which are that ball again.
constexpr double kMinVoteSupport = 0.08;
constexpr std::size_t kMaxCandidates = 400;
constexpr double kExplainedRadii = 0.3, kExplainedScore = 0.9;
// The frame's colours are read over the table and kWindowRadiiAroundTable of the largest ball
// radius around it (an outline's window around a ball on the cushion).
constexpr double kWindowRadiiAroundTable = 3.0;
// Unless given, the balls' scale is settled on the first frame with balls: from those scoring at
// least kSettlingScore, and if it changes by more than kSettledScaleChange they are looked for
// again. A measured scale is at most the balls': the outlines it is measured on follow the radius
// they start from, and an edge inside a ball as strong as its outline (the dark ring a sharpening
// camera draws inside a white ball's edge, a stripe's cap) holds them inside it; never outside,
// where the cloth is. So each of kLargerScales times it is tried, and the largest taken that makes
// kSureGain more of the frame's balls sure (at least one more): a scale too large makes fewer.
constexpr double kSettlingScore = 0.8;
constexpr double kSettledScaleChange = 0.05;
constexpr double kLargerScales[] = {1.1, 1.2};
constexpr double kSureGain = 0.2;
// Two balls' centres are at least two radii apart on the table; closer than kOverlapRadii radii
// (touching balls' outlines fitted a little large, or a ball's shadow beside it) only the better
// is kept.
constexpr double kOverlapRadii = 1.75;
// A frame whose cloth changes colour by more than kNoisyEdges L*a*b* units per pixel (a camera's
// heavy sensor noise; the clean real and rendered frames are 0.2-2.5) is smoothed by a Gaussian
// of kNoiseSmoothingPx before its balls are looked for, as Canny (1986) smooths before finding
// edges: the noise would otherwise be edges everywhere, and weaken a ball's own.
constexpr double kNoisyEdges = 4.0, kNoiseSmoothingPx = 1.5;
// Before a table is learnt, RefineAt takes the cloth's colour as the median of kRingSamples
// pixels on a circle of kRingRadii radii around the prediction, and its edge noise as
// kUnknownEdgeNoise L*a*b* units per pixel (a clean 8-bit frame's: a level of L* is 0.4).
constexpr double kUnknownEdgeNoise = 1.0;
constexpr int kRingSamples = 64;
constexpr double kRingRadii = 2.5;

cv::Mat AsBgr(const cv::Mat& image) {
  if (image.type() == CV_8UC3) return image;
  if (image.type() == CV_8UC1) {
    cv::Mat bgr;
    cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
    return bgr;
  }
  throw std::invalid_argument("ball detector: the frame must be 8-bit BGR or grey");
}

}  // namespace

double ExpectedRadiusPx(const camera::CameraModel& camera, double ball_radius) {
  const Eigen::Vector3d centre =
      camera.Unproject({0.5 * (camera.width - 1), 0.5 * (camera.height - 1)}, ball_radius);
  return ball_radius / camera.MetresPerPixel(centre);
}

BallDetector::BallDetector(DetectorOptions options) : options_(options) {
  PrepareLabConversion();
}

bool BallDetector::LearnTable(const cv::Mat& image) {
  const cv::Mat bgr = AsBgr(image);
  std::optional<TableRegion> table = LookForTable(bgr);
  const auto a_table = [](const std::optional<TableRegion>& t) {
    return t && t->origin != TableOrigin::kClothOnly;
  };
  if (!a_table(table) && a_table(table_) && bgr.size() == frame_size_) {
    return false;  // the table learnt before stands: an arm across a side does not unlearn it
  }
  frame_size_ = bgr.size();
  table_ = std::move(table);
  scale_.reset();
  cloth_ = {};
  smoothing_px_ = 0;
  if (!table_) return false;
  cloth_ = LearnClothModel(bgr, *table_);
  unsmoothed_edge_noise_ = cloth_.edge_noise;
  smoothing_px_ = cloth_.edge_noise > kNoisyEdges ? kNoiseSmoothingPx : 0.0;
  const cv::Mat searched = Smoothed(bgr);
  if (smoothing_px_ > 0) cloth_ = LearnClothModel(searched, *table_);
  scale_settled_ = options_.ball_radius_px > 0;
  if (scale_settled_) {
    scale_ = BallScale{table_->inverse_depth, options_.ball_radius_px};
  } else {
    scale_ = ScaleFromBlobs(searched, *table_, cloth_, LeastPlausibleScale());
    if (!scale_) scale_ = ScaleFromTable(*table_, options_.ball_to_table_width);
  }
  outline_ = TableOutline(bgr, table_->cloth_corners);
  return failure_.empty();
}

double BallDetector::LeastPlausibleScale() const {
  const bool completed = table_ && table_->side_out_of_frame >= 0;
  if (!table_ || table_->origin == TableOrigin::kClothOnly ||
      (!completed && CutByFrame(*table_, frame_size_))) {
    return 0;
  }
  return estimator::LeastPlausibleScale(*table_, options_.ball_set);
}

std::optional<TableRegion> BallDetector::LookForTable(const cv::Mat& bgr) {
  failure_.clear();
  if (options_.calibrated) return TableSeenBy(*options_.calibrated, bgr);
  TableSearch search = FindTable(bgr);
  failure_ = search.reason;
  if (search.table) return search.table;
  return ClothWithBalls(bgr, search);
}

double BallDetector::OutlineAgreement(const cv::Mat& image) const {
  if (image.size() != frame_size_) return 1.0;
  return outline_.Agreement(AsBgr(image));
}

std::vector<BallDetection> BallDetector::Detect(const cv::Mat& image) {
  const cv::Mat raw = AsBgr(image);
  // A frame whose table was not found is looked at again: this one may show it.
  if (raw.size() != frame_size_ || !table_ || table_->origin == TableOrigin::kClothOnly) {
    LearnTable(raw);
  }
  if (!table_) return {};
  const cv::Mat bgr = Smoothed(raw);
  const bool settling = !scale_settled_;
  std::vector<BallDetection> balls =
      FindBalls(bgr, settling ? Doubts::kAsVoted : Doubts::kVotedAgain);
  if (settling) {
    // The scales are compared on the votes alone, which are alike for all the balls at each; the
    // balls are then found again with their doubts voted on.
    SettleScale(bgr, &balls);
    balls = FindBalls(bgr, Doubts::kVotedAgain);
  }
  Name(bgr, &balls);
  return balls;
}

void BallDetector::Identify(const cv::Mat& image, std::vector<BallDetection>* balls) const {
  Name(SearchedFrame(image), balls);
}

cv::Mat BallDetector::SearchedFrame(const cv::Mat& image) const { return Smoothed(AsBgr(image)); }

void BallDetector::Name(const cv::Mat& bgr, std::vector<BallDetection>* balls) const {
  const std::vector<BallIdentity> identities =
      IdentifyBalls(bgr, *balls, options_.ball_set, options_.identity);
  for (std::size_t i = 0; i < balls->size(); ++i) {
    (*balls)[i].ball_class = identities[i].ball_class;
    (*balls)[i].class_confidence = identities[i].confidence;
  }
}

void BallDetector::SettleScale(const cv::Mat& bgr, std::vector<BallDetection>* balls) {
  std::vector<BallOutline> outlines;
  for (const BallDetection& ball : *balls) {
    if (ball.score < kSettlingScore) continue;
    BallOutline outline;
    outline.centre = ball.pixel;
    outline.radius = ball.radius_px;
    outline.supporting_rays = kOutlineRays;
    outlines.push_back(outline);
  }
  const std::optional<BallScale> settled =
      ScaleFromOutlines(*table_, outlines, LeastPlausibleScale());
  if (!settled) return;  // nothing sure yet: an empty table so far
  scale_settled_ = true;
  const double change = settled->radius_at_centre / scale_->radius_at_centre;
  if (std::abs(change - 1.0) > kSettledScaleChange) {
    scale_ = settled;
    *balls = FindBalls(bgr, Doubts::kAsVoted);
  }
  TryLargerScales(bgr, balls);
}

void BallDetector::TryLargerScales(const cv::Mat& bgr, std::vector<BallDetection>* balls) {
  const auto sure = [](const std::vector<BallDetection>& found) {
    return static_cast<double>(std::count_if(
        found.begin(), found.end(), [](const BallDetection& b) { return b.score >= kSureScore; }));
  };
  const BallScale measured = *scale_;
  BallScale best = measured;
  double most = sure(*balls);
  for (const double larger : kLargerScales) {
    scale_ = BallScale{measured.inverse_depth, larger * measured.radius_at_centre};
    std::vector<BallDetection> found = FindBalls(bgr, Doubts::kAsVoted);
    const double now = sure(found);
    if (now >= most + std::max(1.0, kSureGain * most)) {
      best = *scale_;
      most = now;
      *balls = std::move(found);
    }
  }
  scale_ = best;
}

std::vector<BallDetection> BallDetector::FindBalls(const cv::Mat& bgr, Doubts doubts) const {
  // The table and a ball's width around it: every outline and every vote's edge is there.
  double largest = 0;
  for (const auto& c : table_->cloth_corners) largest = std::max(largest, scale_->RadiusAt(c));
  const int margin = static_cast<int>(std::ceil(kWindowRadiiAroundTable * largest));
  const LabImage lab(
      bgr, table_->Bounds() + cv::Size(2 * margin, 2 * margin) - cv::Point(margin, margin));
  const std::vector<CircleVote> peaks = VoteForCircles(bgr, *table_, *scale_, kMinVoteSupport);
  std::vector<std::pair<BallDetection, double>> outlined;  // with their vote support
  for (std::size_t i = 0; i < peaks.size() && i < kMaxCandidates; ++i) {
    const CircleVote& peak = peaks[i];
    const double radius = scale_->RadiusAt(peak.pixel);
    const bool explained = std::any_of(outlined.begin(), outlined.end(), [&](const auto& o) {
      return o.first.score >= kExplainedScore &&
             (o.first.pixel - peak.pixel).norm() < kExplainedRadii * radius;
    });
    if (explained) continue;
    const auto outline = FitBallOutline(lab, peak.pixel, radius, EdgeThreshold(cloth_.edge_noise),
                                        NearCushion(*table_, radius));
    if (!outline || !OnTable(*table_, outline->centre, radius)) continue;
    const auto score_for = [&](double support) {
      return EvidenceForBall(bgr, lab, *outline, radius,
                             {cloth_.ColourAt(outline->centre), cloth_.noise}, support)
          .Score();
    };
    double score = score_for(peak.support);
    if (doubts == Doubts::kVotedAgain && score >= options_.min_score && score < kSureScore) {
      score = std::max(score, score_for(FullResolutionSupport(bgr, outline->centre,
                                                              outline->radius,
                                                              cloth_.edge_noise)));
    }
    if (InPocketMouth(*table_, outline->centre, radius, score)) continue;
    outlined.push_back({{outline->centre, outline->radius, score}, peak.support});
  }
  // Best first; among outlines of one ball (from a peak at its centre, or between it and its
  // shadow) that its own outline voted for most.
  const auto rank = [](const auto& o) { return o.first.score * (0.5 + o.second); };
  std::sort(outlined.begin(), outlined.end(),
            [&](const auto& a, const auto& b) { return rank(a) > rank(b); });
  std::vector<BallDetection> balls;
  for (const auto& [ball, support] : outlined) {
    if (ball.score < options_.min_score) continue;
    const bool overlaps = std::any_of(balls.begin(), balls.end(), [&](const BallDetection& b) {
      return table_->TableDistancePx(b.pixel, ball.pixel) <
             kOverlapRadii * std::max(b.radius_px, ball.radius_px);
    });
    if (!overlaps) balls.push_back(ball);
  }
  std::vector<BallDetection> on_cloth = OnCloth(bgr, *table_, cloth_, *scale_, balls);
  for (BallDetection& ball : on_cloth) {
    ball.pixel = CentreOnChroma(lab, ball.pixel, ball.radius_px, EdgeThreshold(cloth_.edge_noise),
                                NearCushion(*table_, ball.radius_px));
  }
  return on_cloth;
}

cv::Mat BallDetector::Smoothed(const cv::Mat& bgr) const {
  if (smoothing_px_ <= 0) return bgr;
  cv::Mat smoothed;
  cv::GaussianBlur(bgr, smoothed, {0, 0}, smoothing_px_);
  return smoothed;
}

std::optional<BallDetection> BallDetector::RefineAt(const cv::Mat& image,
                                                    const Eigen::Vector2d& predicted,
                                                    double radius_px) const {
  const cv::Mat bgr = AsBgr(image);
  cv::Vec3f cloth;
  // The frame is not smoothed here: the outline is looked for only near the prediction, where a
  // noisy camera's edges compete less, and smoothing every frame would cost the tracker its speed.
  double edge_noise = unsmoothed_edge_noise_;
  if (!cloth_.empty()) {
    cloth = cloth_.ColourAt(predicted);
  } else {
    std::array<std::vector<uint8_t>, 3> ring;
    for (int k = 0; k < kRingSamples; ++k) {
      const double angle = 2 * M_PI * k / kRingSamples;
      const int x =
          static_cast<int>(std::lround(predicted.x() + kRingRadii * radius_px * std::cos(angle)));
      const int y =
          static_cast<int>(std::lround(predicted.y() + kRingRadii * radius_px * std::sin(angle)));
      if (x < 0 || y < 0 || x >= bgr.cols || y >= bgr.rows) continue;
      for (int c = 0; c < 3; ++c) ring[c].push_back(bgr.at<cv::Vec3b>(y, x)[c]);
    }
    if (ring[0].empty()) return std::nullopt;
    for (int c = 0; c < 3; ++c) {
      std::nth_element(ring[c].begin(), ring[c].begin() + ring[c].size() / 2, ring[c].end());
      cloth[c] = ring[c][ring[c].size() / 2];
    }
    edge_noise = kUnknownEdgeNoise;
  }
  const LabImage lab(bgr, OutlineWindow(predicted, radius_px));
  const Occluder near_cushion = table_ ? NearCushion(*table_, radius_px) : Occluder();
  const auto outline =
      FitBallOutline(lab, predicted, radius_px, EdgeThreshold(edge_noise), near_cushion);
  if (!outline) return std::nullopt;
  const double score =
      EvidenceForBall(bgr, lab, *outline, radius_px, {cloth, cloth_.noise}, 1.0).Score();
  if (score < kSureScore) return std::nullopt;
  return BallDetection{CentreOnChroma(lab, outline->centre, outline->radius,
                                      EdgeThreshold(edge_noise), near_cushion),
                       outline->radius, score};
}

}  // namespace billiard::estimator
