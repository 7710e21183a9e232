#include "estimator/ball_score.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace billiard::estimator {

namespace {

constexpr double kOutlineFrom = 0.45, kOutlineWidth = 0.35;
constexpr double kMaxGap = 0.9 * M_PI;
constexpr double kSizeTolerance = 0.25;
constexpr double kVotesFrom = 0.08, kVotesWidth = 0.25;
constexpr double kColourFrom = 8.0, kColourWidth = 12.0;
constexpr double kShineFrom = 15.0, kShineWidth = 20.0;
constexpr double kShinePercentile = 0.98;
// The colour is measured over the disc of kColourRadii of the fitted radius (inside the blur of
// the outline), the shine over kShineRadii (a highlight may sit near the rim).
constexpr double kColourRadii = 0.7, kShineRadii = 0.85;

double Ramp(double x, double from, double width) {
  return std::clamp((x - from) / width, 0.0, 1.0);
}

// The median colour distance from the cloth and the shine (98th percentile less the median of
// L*) of the ball's disc; false when the disc is outside the frame.
bool MeasureLook(const LabImage& lab, const BallOutline& outline, const cv::Vec3f& cloth,
                 double* colour_distance, double* shine) {
  const double reach = kShineRadii * outline.radius;
  const cv::Rect rect =
      cv::Rect(static_cast<int>(std::floor(outline.centre.x() - reach)),
               static_cast<int>(std::floor(outline.centre.y() - reach)),
               static_cast<int>(2 * reach) + 2, static_cast<int>(2 * reach) + 2) &
      lab.region();
  if (rect.empty()) return false;
  const double colour_reach2 = std::pow(kColourRadii * outline.radius, 2);
  std::vector<float> distances, lightness;
  for (int y = rect.y; y < rect.y + rect.height; ++y) {
    const double dy = y - outline.centre.y();
    for (int x = rect.x; x < rect.x + rect.width; ++x) {
      const double dx = x - outline.centre.x();
      const double d2 = dx * dx + dy * dy;
      if (d2 > reach * reach) continue;
      const cv::Vec3f colour = lab.Pixel(x, y);
      lightness.push_back(colour[0]);
      if (d2 <= colour_reach2) distances.push_back(static_cast<float>(cv::norm(colour - cloth)));
    }
  }
  if (distances.empty() || lightness.empty()) return false;
  std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
  *colour_distance = distances[distances.size() / 2];
  std::sort(lightness.begin(), lightness.end());
  *shine = lightness[static_cast<std::size_t>(kShinePercentile * (lightness.size() - 1))] -
           lightness[lightness.size() / 2];
  return true;
}

}  // namespace

double BallEvidence::Score() const { return std::sqrt(outline * size * votes * look); }

BallEvidence EvidenceForBall(const LabImage& lab, const BallOutline& outline,
                             double expected_radius, const cv::Vec3f& cloth,
                             double vote_support) {
  BallEvidence evidence;
  evidence.outline =
      outline.largest_gap < kMaxGap
          ? Ramp(static_cast<double>(outline.supporting_rays) / kOutlineRays, kOutlineFrom,
                 kOutlineWidth)
          : 0.0;
  const double q = (outline.radius / expected_radius - 1.0) / kSizeTolerance;
  evidence.size = std::clamp(1.0 - q * q, 0.0, 1.0);
  evidence.votes = Ramp(vote_support, kVotesFrom, kVotesWidth);
  double colour_distance = 0, shine = 0;
  if (MeasureLook(lab, outline, cloth, &colour_distance, &shine)) {
    evidence.look = std::max(Ramp(colour_distance, kColourFrom, kColourWidth),
                             Ramp(shine, kShineFrom, kShineWidth));
  }
  return evidence;
}

}  // namespace billiard::estimator
