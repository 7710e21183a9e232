#include "estimator/ball_placement.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "estimator/ball_score.h"
#include "estimator/local_cloth.h"
#include "estimator/not_cloth.h"
#include "estimator/table_edges.h"

namespace billiard::estimator {

using internal::Contrast;
using internal::Decompose;
using internal::LocalCloth;
using internal::MakeLocalCloth;

namespace {

// Where a ball may be: its centre is a radius inside the cushions' noses. Those are found less
// surely than the cloth's outline (an old cloth's worn track, a cushion's face hidden), so a ball
// is only held to them near a pocket (within kPocketRadii of a corner or the middle of a side),
// where pocket liners and holes look like balls, and taken up to kOffSurfaceRadii outside them;
// elsewhere its centre may be up to kOffClothRadii outside the cloth's outline (which a dark edge
// of the cloth, in the cushion's shade, can pull in). Only a sure outline (kSureScore,
// ball_score.h) is taken outside the noses near a pocket: an unsure one there is the pocket's dark
// mouth between its jaws, its rim outlined.
constexpr double kPocketRadii = 3.0;
// The near cushion's nose hides what lies beyond it less kNoseMarginPx (or kNoseMarginRadii of a
// radius): its own edge, found that close to the line fitted through it.
constexpr double kNoseMarginPx = 1.5, kNoseMarginRadii = 0.1;
constexpr double kOffSurfaceRadii = 0.5;
constexpr double kOffClothRadii = 0.5;
// A ball whose centre is beyond that (against the far cushion in a low view, its centre seen above
// the cushion's foot) is on the table where it touches the cloth (GroundPoint) at least
// kGroundInsideRadii of its radius inside the noses: a ball against a cushion touches it at the
// nose's height (63.5 % of its diameter, WPA), its centre 0.96 of a radius inside; the rest is
// the sides' error. What lies on a cushion's top or face is farther out.
constexpr double kGroundInsideRadii = 0.5;
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
constexpr double kMinSurroundSeen = 0.25;

bool NearPocket(const TableRegion& table, const Eigen::Vector2d& centre, double radius) {
  const auto pockets = table.PocketPlaces();
  return std::any_of(pockets.begin(), pockets.end(),
                     [&](const auto& p) { return (p - centre).norm() < kPocketRadii * radius; });
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

}  // namespace

Eigen::Vector2d GroundPoint(const TableRegion& table, const Eigen::Vector2d& centre,
                            double radius) {
  const Eigen::JacobiSVD<Eigen::Matrix2d> svd(table.JacobianAt(centre), Eigen::ComputeFullU);
  const Eigen::Vector2d axes = svd.singularValues();
  if (!(axes(0) > 0)) return centre;
  const double sin_elevation = std::clamp(axes(1) / axes(0), 0.0, 1.0);
  Eigen::Vector2d towards_camera = svd.matrixU().col(1);
  if (towards_camera.dot(table.inverse_depth.head<2>()) < 0) towards_camera = -towards_camera;
  return centre + radius * std::sqrt(1.0 - sin_elevation * sin_elevation) * towards_camera;
}

bool OnTable(const TableRegion& table, const Eigen::Vector2d& centre, double radius) {
  if (table.InsideCloth(centre, -kOffClothRadii * radius) &&
      (!NearPocket(table, centre, radius) || table.Contains(centre, -kOffSurfaceRadii * radius))) {
    return true;
  }
  // In an oblique view (from overhead, the cloth-only region's too, the centre is where the ball
  // touches the cloth), a ball against a cushion: where it touches the cloth, well inside the
  // noses.
  if (table.view != TableView::kOblique) return false;
  const Eigen::Vector2d ground = GroundPoint(table, centre, radius);
  const Eigen::Vector2d t = table.TableAt(ground);
  const double inside =
      std::min(std::min(t.x(), kTableAspect - t.x()), std::min(t.y(), 1.0 - t.y()));
  return inside >= kGroundInsideRadii * radius / table.PixelsPerWidthAt(ground);
}

bool InPocketMouth(const TableRegion& table, const Eigen::Vector2d& centre, double radius,
                   double score) {
  return score < kSureScore && NearPocket(table, centre, radius) && !table.Contains(centre);
}

Occluder NearCushion(const TableRegion& table, double radius) {
  if (table.view != TableView::kOblique) return {};
  int near = 0;
  double nearest = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    const double depth =
        table.InverseDepthAt(0.5 * (table.corners[i] + table.corners[(i + 1) % 4]));
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

}  // namespace billiard::estimator
