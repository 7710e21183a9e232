#include "estimator/ball_detector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "estimator/ball_identity.h"
#include "estimator/ball_score.h"
#include "estimator/circle_votes.h"
#include "estimator/lab_image.h"
#include "estimator/local_cloth.h"
#include "estimator/not_cloth.h"
#include "estimator/table_fallback.h"

namespace billiard::estimator {

using internal::Contrast;
using internal::Decompose;
using internal::LocalCloth;
using internal::MakeLocalCloth;

namespace {

// The cloth's colour map has kClothCells cells across the table's search mask; a cell with less
// than kMinCellCloth of its area cloth takes its neighbours' colour.
constexpr int kClothCells = 24;
constexpr double kMinCellCloth = 0.2;
// An edge is a colour change of at least kEdgeNoises times the cloth's own, and never less than
// kMinEdge L*a*b* units per pixel (a clean frame's cloth has almost no noise, and the least
// ball, black on navy, changes by several units per pixel).
constexpr double kEdgeNoises = 1.5, kMinEdge = 2.0;
// The balls' scale is measured on the compact blobs of not-cloth (not_cloth.h): blobs of at least
// kMinBlobArea of its pixels, about as wide as high (kMaxBlobAspect), filling at least
// kMinBlobFill of their bounding ellipse; their outlines count with kMinScaleSupport of the rays.
constexpr int kMinBlobArea = 12;
constexpr double kMaxBlobAspect = 1.55;
constexpr double kMinBlobFill = 0.75;
constexpr double kMinScaleSupport = 0.35;
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
// Where a ball may be: its centre is a radius inside the cushions' noses. Those are found less
// surely than the cloth's outline (an old cloth's worn track, a cushion's face hidden), so a ball
// is only held to them near a pocket (within kPocketRadii of a corner or the middle of a side),
// where pocket liners and holes look like balls, and taken up to kOffSurfaceRadii outside them;
// elsewhere its centre may be up to kOffClothRadii outside the cloth's outline (which a dark edge
// of the cloth, in the cushion's shade, can pull in). Only a sure outline (kSureScore, below) is
// taken outside the noses near a pocket: an unsure one there is the pocket's dark mouth between
// its jaws, its rim outlined.
constexpr double kPocketRadii = 3.0;
// The near cushion's nose hides what lies beyond it less kNoseMarginPx (or kNoseMarginRadii of a
// radius): its own edge, found that close to the line fitted through it.
constexpr double kNoseMarginPx = 1.5, kNoseMarginRadii = 0.1;
constexpr double kOffSurfaceRadii = 0.5;
constexpr double kOffClothRadii = 0.5;
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
// A ball lies on the cloth: on a circle of kSurroundRadii radii around it (past its shadow's
// darkest part, short of a touching neighbour's far side), at kSurroundSamples places, what is on
// the playing surface and not cloth (in any light, local_cloth.h) is another ball kept. An unsure
// outline (scoring less than kSureScore) with more than kMaxForeignSurround of that circle's
// places on the surface on something else lies on a hand, an arm, a sleeve, a cue's butt or a
// pocket's liner. So does an unsure outline whose centre lies on what leans over the table (an
// intruder, not_cloth.h: an arm and the dark glove at its end), however much cloth shows between
// the fingers around it. A sure one stands unless both (a logo on a cap): a ball of a rack whose
// neighbours were not all found is surrounded by balls, not cloth. With less than
// kMinSurroundSeen of the circle on the surface (a ball in a corner of a surface found too small)
// the surround is not judged.
constexpr double kSurroundRadii = 1.5;
constexpr int kSurroundSamples = 64;
constexpr double kMaxForeignSurround = 0.6;
constexpr double kSureScore = 0.8;
constexpr double kMinSurroundSeen = 0.25;
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

bool NearPocket(const TableRegion& table, const Eigen::Vector2d& centre, double radius) {
  const auto pockets = table.PocketPlaces();
  return std::any_of(pockets.begin(), pockets.end(),
                     [&](const auto& p) { return (p - centre).norm() < kPocketRadii * radius; });
}

bool OnTable(const TableRegion& table, const Eigen::Vector2d& centre, double radius) {
  if (!table.InsideCloth(centre, -kOffClothRadii * radius)) return false;
  return !NearPocket(table, centre, radius) || table.Contains(centre, -kOffSurfaceRadii * radius);
}

// Whether an outline scoring `score` is a pocket's mouth rather than a ball (kPocketRadii).
bool InPocketMouth(const TableRegion& table, const Eigen::Vector2d& centre, double radius,
                   double score) {
  return score < kSureScore && NearPocket(table, centre, radius) && !table.Contains(centre);
}

// The near cushion's nose in an oblique view, as an occluder of the balls against it: the cushion
// stands between the camera and such a ball and hides its lower part, which is not missing from
// its outline but out of view. The near side is the one nearest the camera (the largest inverse
// depth at its middle); an overhead camera sees every ball whole.
Occluder NearCushion(const TableRegion& table, double radius) {
  if (table.view != TableView::kOblique) return {};
  int near = 0;
  double nearest = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    const double depth = table.InverseDepthAt(0.5 * (table.corners[i] + table.corners[(i + 1) % 4]));
    if (depth > nearest) {
      nearest = depth;
      near = i;
    }
  }
  const Eigen::Vector2d a = table.corners[near];
  const Eigen::Vector2d along = (table.corners[(near + 1) % 4] - a).normalized();
  Eigen::Vector2d normal(along.y(), -along.x());
  if (normal.dot(table.Centre() - a) > 0) normal = -normal;
  return {normal, normal.dot(a), std::max(kNoseMarginPx, kNoseMarginRadii * radius)};
}

// The share of the places on the playing surface of the circle around `ball` (kSurroundRadii) on
// neither cloth nor a sure ball of `balls`.
double ForeignSurround(const cv::Mat& bgr, const TableRegion& table, const ClothModel& cloth,
                       const BallDetection& ball, const std::vector<BallDetection>& balls) {
  int foreign = 0, seen = 0;
  for (int k = 0; k < kSurroundSamples; ++k) {
    const double angle = 2 * M_PI * k / kSurroundSamples;
    const Eigen::Vector2d p = ball.pixel + kSurroundRadii * ball.radius_px *
                                              Eigen::Vector2d(std::cos(angle), std::sin(angle));
    const int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
    if (x < 0 || y < 0 || x >= bgr.cols || y >= bgr.rows || !table.Contains(p)) continue;
    ++seen;
    const bool on_ball = std::any_of(balls.begin(), balls.end(), [&](const BallDetection& b) {
      return &b != &ball && (b.pixel - p).norm() < b.radius_px * 1.15;
    });
    if (on_ball) continue;
    const cv::Vec3b c = bgr.at<cv::Vec3b>(y, x);
    const LocalCloth local = MakeLocalCloth(cloth.ColourAt(p), cloth.noise);
    float along, across;
    Decompose(cv::Vec3f(c[0], c[1], c[2]), local, &along, &across);
    foreign += Contrast(along, across, local) >= 1.0f;
  }

  return seen >= kMinSurroundSeen * kSurroundSamples ? static_cast<double>(foreign) / seen : 0.0;
}

// Whether a full-resolution pixel lies on one of `intruders` (NotClothMap::Intruders).
bool OnIntruder(const NotClothMap& not_cloth, const cv::Mat& intruders,
                const Eigen::Vector2d& pixel) {
  const Eigen::Vector2d p = not_cloth.ToMap(pixel);
  const int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
  return x >= 0 && y >= 0 && x < intruders.cols && y < intruders.rows &&
         intruders.at<uint8_t>(y, x) != 0;
}

// The balls on the cloth: an unsure one is not when it is mostly surrounded by something else
// (ForeignSurround) or lies on what leans over the table (an intruder of not_cloth.h); a sure one
// only when both (a logo on a player's cap, a knuckle in the middle of a hand), for a ball is
// never under an arm and a sure ball in a rack is surrounded by balls that were not all found.
// The intruders are looked for only when a ball needs them.
std::vector<BallDetection> OnCloth(const cv::Mat& bgr, const TableRegion& table,
                                   const ClothModel& cloth, const BallScale& scale,
                                   const std::vector<BallDetection>& balls) {
  std::optional<NotClothMap> not_cloth;
  cv::Mat intruders;
  const auto on_intruder = [&](const BallDetection& ball) {
    if (!not_cloth) {
      not_cloth.emplace(bgr, table, cloth, NotClothMap::IntruderFactor(scale));
      intruders = not_cloth->Intruders(scale);
    }
    return OnIntruder(*not_cloth, intruders, ball.pixel);
  };
  std::vector<BallDetection> kept;
  for (const BallDetection& ball : balls) {
    const bool surrounded = ForeignSurround(bgr, table, cloth, ball, balls) > kMaxForeignSurround;
    const bool sure = ball.score >= kSureScore;
    if (sure ? surrounded && on_intruder(ball) : surrounded || on_intruder(ball)) continue;
    kept.push_back(ball);
  }
  return kept;
}

// The outline's band for OutlineAgreement: kOutlineBandPx either side of the cloth's outline at
// the table search's resolution (the frame's longer side at most kTableSearchSize pixels).
constexpr int kOutlineBandPx = 3;

int OutlineFactor(const cv::Size& size) {
  return static_cast<int>(std::ceil(std::max(size.width, size.height) / kTableSearchSize));
}

// The gradient magnitude of a frame's grey levels at the table search's resolution.
cv::Mat OutlineGradient(const cv::Mat& bgr) {
  const int factor = OutlineFactor(bgr.size());
  cv::Mat small, grey, gx, gy, magnitude;
  cv::resize(bgr, small, {}, 1.0 / factor, 1.0 / factor, cv::INTER_AREA);
  cv::cvtColor(small, grey, cv::COLOR_BGR2GRAY);
  grey.convertTo(grey, CV_32F);
  cv::Sobel(grey, gx, CV_32F, 1, 0);
  cv::Sobel(grey, gy, CV_32F, 0, 1);
  cv::magnitude(gx, gy, magnitude);
  return magnitude;
}

double MinEdge(double edge_noise) { return std::max(kMinEdge, kEdgeNoises * edge_noise); }

cv::Mat AsBgr(const cv::Mat& image) {
  if (image.type() == CV_8UC3) return image;
  if (image.type() == CV_8UC1) {
    cv::Mat bgr;
    cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
    return bgr;
  }
  throw std::invalid_argument("ball detector: the frame must be 8-bit BGR or grey");
}

// Fills cells without an estimate from their neighbours (normalized convolution), widening until
// every cell has one.
void FillMissing(cv::Mat& colour, cv::Mat& weight) {
  for (int k = 3; k < 4 * std::max(colour.rows, colour.cols); k = 2 * k + 1) {
    double min_weight;
    cv::minMaxLoc(weight, &min_weight);
    if (min_weight > 0) break;
    cv::Mat weighted, blurred_weight, blurred;
    std::vector<cv::Mat> channels;
    cv::split(colour, channels);
    for (auto& c : channels) c = c.mul(weight);
    cv::merge(channels, weighted);
    cv::blur(weighted, blurred, {k, k}, {-1, -1}, cv::BORDER_REPLICATE);
    cv::blur(weight, blurred_weight, {k, k}, {-1, -1}, cv::BORDER_REPLICATE);
    for (int y = 0; y < colour.rows; ++y) {
      for (int x = 0; x < colour.cols; ++x) {
        const float w = blurred_weight.at<float>(y, x);
        if (weight.at<float>(y, x) == 0 && w > 0) {
          colour.at<cv::Vec3f>(y, x) = blurred.at<cv::Vec3f>(y, x) / w;
          weight.at<float>(y, x) = 1e-3f;
        }
      }
    }
  }
}

// The cloth's local colour, from the table's cloth pixels, and its spread across its own colour.
ClothModel LearnClothModel(const cv::Mat& bgr, const TableRegion& table) {
  cv::Mat small;
  cv::resize(bgr, small, table.cloth.size(), 0, 0, cv::INTER_AREA);
  const int cell = std::max(4, small.cols / kClothCells);
  const cv::Size cells((small.cols + cell - 1) / cell, (small.rows + cell - 1) / cell);
  cv::Mat sum(cells, CV_32FC3, cv::Scalar::all(0)), weight(cells, CV_32F, cv::Scalar(0));
  for (int y = 0; y < small.rows; ++y) {
    const auto* in = small.ptr<cv::Vec3b>(y);
    const auto* cloth = table.cloth.ptr<uint8_t>(y);
    for (int x = 0; x < small.cols; ++x) {
      if (!cloth[x]) continue;
      sum.at<cv::Vec3f>(y / cell, x / cell) += cv::Vec3f(in[x][0], in[x][1], in[x][2]);
      weight.at<float>(y / cell, x / cell) += 1.0f;
    }
  }
  cv::Mat colour(cells, CV_32FC3, cv::Scalar::all(0));
  for (int y = 0; y < cells.height; ++y) {
    for (int x = 0; x < cells.width; ++x) {
      float& w = weight.at<float>(y, x);
      if (w < kMinCellCloth * cell * cell) {
        w = 0;
      } else {
        colour.at<cv::Vec3f>(y, x) = sum.at<cv::Vec3f>(y, x) / w;
      }
    }
  }
  FillMissing(colour, weight);
  ClothModel model;
  model.colour = colour;
  model.cell = cell / table.mask_scale;
  std::vector<float> across;
  for (int y = 0; y < small.rows; y += 2) {
    for (int x = 0; x < small.cols; x += 2) {
      if (!table.cloth.at<uint8_t>(y, x)) continue;
      const cv::Vec3b p = small.at<cv::Vec3b>(y, x);
      float along, distance;
      Decompose(cv::Vec3f(p[0], p[1], p[2]),
                MakeLocalCloth(colour.at<cv::Vec3f>(y / cell, x / cell), 0.0), &along, &distance);
      across.push_back(distance);
    }
  }
  if (!across.empty()) {
    std::nth_element(across.begin(), across.begin() + across.size() / 2, across.end());
    model.noise = 1.4826 * across[across.size() / 2];
  }
  model.edge_noise = EdgeNoise(LabImage(bgr, table.Bounds()), table);
  return model;
}

// The outlines of the compact blobs of not-cloth on the table: mostly single balls, whose radii
// give the scale.
std::vector<BallOutline> BlobOutlines(const cv::Mat& bgr, const TableRegion& table,
                                      const ClothModel& cloth) {
  const NotClothMap not_cloth(bgr, table, cloth, NotClothMap::BlobFactor(table));
  if (not_cloth.mask().empty()) return {};
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(not_cloth.mask(), labels, stats, centroids, 8);
  const LabImage lab(bgr, not_cloth.region());
  std::vector<BallOutline> outlines;
  for (int i = 1; i < n; ++i) {
    const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    const int area = stats.at<int>(i, cv::CC_STAT_AREA);
    const double aspect = static_cast<double>(std::max(w, h)) / std::min(w, h);
    const double fill = area / (0.25 * M_PI * w * h);
    if (area < kMinBlobArea || aspect > kMaxBlobAspect || fill < kMinBlobFill) continue;
    const Eigen::Vector2d centroid(centroids.at<double>(i, 0), centroids.at<double>(i, 1));
    const auto outline = FitBallOutline(lab, not_cloth.ToFull(centroid),
                                        not_cloth.factor() * std::sqrt(area / M_PI),
                                        MinEdge(cloth.edge_noise));
    if (outline && outline->supporting_rays >= kMinScaleSupport * kOutlineRays) {
      outlines.push_back(*outline);
    }
  }
  return outlines;
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
    scale_ = ScaleFromOutlines(*table_, BlobOutlines(searched, *table_, cloth_));
    if (!scale_) scale_ = ScaleFromTable(*table_, options_.ball_to_table_width);
  }
  outline_gradient_ = OutlineGradient(bgr);
  outline_band_ = cv::Mat::zeros(outline_gradient_.size(), CV_8U);
  std::vector<cv::Point> outline;
  const double factor = OutlineFactor(bgr.size());
  for (const auto& c : table_->cloth_corners) {
    outline.emplace_back(static_cast<int>(std::lround((c.x() + 0.5) / factor - 0.5)),
                         static_cast<int>(std::lround((c.y() + 0.5) / factor - 0.5)));
  }
  cv::polylines(outline_band_, outline, true, 255, 2 * kOutlineBandPx + 1);
  return failure_.empty();
}

std::optional<TableRegion> BallDetector::LookForTable(const cv::Mat& bgr) {
  failure_.clear();
  if (options_.calibrated) return TableSeenBy(*options_.calibrated, bgr);
  TableSearch search = FindTable(bgr);
  failure_ = search.reason;
  if (search.table) return search.table;
  if (search.cloth) return ClothOnly(*search.cloth);
  return std::nullopt;
}

double BallDetector::OutlineAgreement(const cv::Mat& image) const {
  if (outline_gradient_.empty() || image.size() != frame_size_) return 1.0;
  const cv::Mat now = OutlineGradient(AsBgr(image));
  const cv::Scalar mean_then = cv::mean(outline_gradient_, outline_band_);
  const cv::Scalar mean_now = cv::mean(now, outline_band_);
  double both = 0, then_squares = 0, now_squares = 0;
  for (int y = 0; y < now.rows; ++y) {
    const auto* band = outline_band_.ptr<uint8_t>(y);
    const auto* a = outline_gradient_.ptr<float>(y);
    const auto* b = now.ptr<float>(y);
    for (int x = 0; x < now.cols; ++x) {
      if (!band[x]) continue;
      const double da = a[x] - mean_then[0], db = b[x] - mean_now[0];
      both += da * db;
      then_squares += da * da;
      now_squares += db * db;
    }
  }
  return then_squares > 0 && now_squares > 0 ? both / std::sqrt(then_squares * now_squares) : 0.0;
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
  const std::optional<BallScale> settled = ScaleFromOutlines(*table_, outlines);
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
    const auto outline = FitBallOutline(lab, peak.pixel, radius, MinEdge(cloth_.edge_noise),
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
    ball.pixel = CentreOnChroma(lab, ball.pixel, ball.radius_px, MinEdge(cloth_.edge_noise),
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
  const auto outline = FitBallOutline(lab, predicted, radius_px, MinEdge(edge_noise), near_cushion);
  if (!outline) return std::nullopt;
  const double score =
      EvidenceForBall(bgr, lab, *outline, radius_px, {cloth, cloth_.noise}, 1.0).Score();
  if (score < kSureScore) return std::nullopt;
  return BallDetection{
      CentreOnChroma(lab, outline->centre, outline->radius, MinEdge(edge_noise), near_cushion),
      outline->radius, score};
}

}  // namespace billiard::estimator
