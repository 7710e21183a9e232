#include "estimator/ball_score.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "estimator/local_cloth.h"

namespace billiard::estimator {

using internal::Decompose;
using internal::kDarkRamp;
using internal::kDarkStart;
using internal::LocalCloth;
using internal::MakeLocalCloth;

namespace {

constexpr double kOutlineFrom = 0.45, kOutlineWidth = 0.35;
constexpr double kMaxGap = 0.9 * M_PI;
constexpr double kSizeTolerance = 0.25;
constexpr double kVotesFrom = 0.08, kVotesWidth = 0.25;
constexpr double kNotClothFrom = 0.5, kNotClothWidth = 0.5;
constexpr double kShineFrom = 15.0, kShineWidth = 20.0;
constexpr double kShinePercentile = 0.98;
constexpr double kSphereRimToCore = 0.97, kSphereWidth = 0.1;
// Where each is measured, in fitted radii: the colour over the disc inside the outline's blur,
// the shine out to where a highlight may sit, the sphere's core and rim band.
constexpr double kColourRadii = 0.7, kShineRadii = 0.85;
constexpr double kCoreRadii = 0.5, kRimFrom = 0.65, kRimTo = 0.9;

double Ramp(double x, double from, double width) {
  return std::clamp((x - from) / width, 0.0, 1.0);
}

double Median(std::vector<float>& values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// The look term (see the header); 0 when the disc is outside the frame.
double Look(const cv::Mat& bgr, const LabImage& lab, const BallOutline& outline,
            const ClothColour& cloth) {
  const double reach = kShineRadii * outline.radius;
  const cv::Rect rect = cv::Rect(static_cast<int>(std::floor(outline.centre.x() - reach)),
                                 static_cast<int>(std::floor(outline.centre.y() - reach)),
                                 static_cast<int>(2 * reach) + 2, static_cast<int>(2 * reach) + 2) &
                        lab.region() & cv::Rect(0, 0, bgr.cols, bgr.rows);
  if (rect.empty()) return 0.0;
  const LocalCloth local = MakeLocalCloth(cloth.bgr, cloth.noise);
  std::vector<float> not_cloth, brightness, lightness;
  double core = 0, rim = 0;
  int core_n = 0, rim_n = 0;
  for (int y = rect.y; y < rect.y + rect.height; ++y) {
    const double dy = y - outline.centre.y();
    const auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = rect.x; x < rect.x + rect.width; ++x) {
      const double dx = x - outline.centre.x();
      const double rho = std::sqrt(dx * dx + dy * dy) / outline.radius;
      if (rho > kShineRadii) continue;
      const float l = lab.Pixel(x, y)[0];
      lightness.push_back(l);
      if (rho < kCoreRadii) {
        core += l;
        ++core_n;
      } else if (rho >= kRimFrom && rho <= kRimTo) {
        rim += l;
        ++rim_n;
      }
      if (rho > kColourRadii) continue;
      float along, across;
      Decompose(cv::Vec3f(row[x][0], row[x][1], row[x][2]), local, &along, &across);
      not_cloth.push_back(std::max(across * local.inv_across, (kDarkStart - along) / kDarkRamp));
      brightness.push_back(along);
    }
  }
  if (not_cloth.empty() || core_n == 0 || rim_n == 0) return 0.0;
  double look = Ramp(Median(not_cloth), kNotClothFrom, kNotClothWidth);
  const auto shine_rank =
      lightness.begin() + static_cast<std::ptrdiff_t>(kShinePercentile * (lightness.size() - 1));
  std::nth_element(lightness.begin(), shine_rank, lightness.end());
  const double bright = *shine_rank;
  const double shine = bright - Median(lightness);
  look = std::max(look, Ramp(shine, kShineFrom, kShineWidth));
  if (Median(brightness) > 1.0 && core > 0) {
    look =
        std::max(look, Ramp(kSphereRimToCore - (rim / rim_n) / (core / core_n), 0.0, kSphereWidth));
  }
  return look;
}

}  // namespace

double BallEvidence::Score() const { return std::sqrt(outline * size * votes * look); }

BallEvidence EvidenceForBall(const cv::Mat& bgr, const LabImage& lab, const BallOutline& outline,
                             double expected_radius, const ClothColour& cloth,
                             double vote_support) {
  BallEvidence evidence;
  evidence.outline = outline.largest_gap < kMaxGap
                         ? Ramp(outline.SupportedShare(), kOutlineFrom, kOutlineWidth)
                         : 0.0;
  const double q = (outline.radius / expected_radius - 1.0) / kSizeTolerance;
  evidence.size = std::clamp(1.0 - q * q, 0.0, 1.0);
  evidence.votes = Ramp(vote_support, kVotesFrom, kVotesWidth);
  // The look is the costliest to measure, and moot where the rest already rule a ball out.
  evidence.look =
      evidence.outline * evidence.size * evidence.votes > 0 ? Look(bgr, lab, outline, cloth) : 0.0;
  return evidence;
}

}  // namespace billiard::estimator
