#include "estimator/ball_outline.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace billiard::estimator {

namespace {

// Along a ray, samples every `step` pixels over a range of radii: the first round, from a guess,
// widely and coarsely (kFirstRange radii either side of the radius, every kFirstStepPx), the
// second, from about the centre, narrowly and finely (kSecondRange, kSecondStepPx). An edge
// candidate is a local maximum of the colour's rate of change of at least kEdgeOfRayMax of the
// ray's largest. CentreOnChroma's round places each edge on the chroma (SettledOnChroma).
struct RaySampling {
  double range;       // radii either side of the radius
  double step;        // [px]
  double prior_rays;  // the weight of the radius prior, in rays
  bool on_chroma = false;
};
constexpr RaySampling kRounds[] = {{0.5, 1.0, 0.5}, {0.3, 0.5, 0.5}};
// CentreOnChroma's round: the second round's sampling, from the found centre.
constexpr RaySampling kChromaRound = {kRounds[1].range, kRounds[1].step, kRounds[1].prior_rays,
                                      true};
constexpr double kEdgeOfRayMax = 0.25;
// The window holds every ray from a centre that may move a radius.
constexpr double kWindowRadii = 2.6;
constexpr int kWindowMarginPx = 2;
// The fit: a candidate counts when within kCandidateReach radii of the circle; Tukey's constant
// on the robust scale (never below kMinScalePx); up to kIterations Gauss-Newton steps, ended by a
// step below kStepPx.
constexpr double kCandidateReach = 0.35;
constexpr double kTukey = 4.685;
constexpr double kMinScalePx = 0.4;
constexpr int kIterations = 8;
constexpr double kStepPx = 1e-3;
constexpr int kMinCandidateRays = 6;
// A fit that moves more than kMaxShiftRadii or changes the radius by more than kMaxRadiusChange
// (relative) found something else.
constexpr double kMaxShiftRadii = 1.0, kMaxRadiusChange = 0.4;
// A guess beyond an occluder starts kInViewRadii radii on this side of it (InView).
constexpr double kInViewRadii = 0.25;
// A ray supports the circle with an edge within max(kSupportPx, kSupportRadii r) of it.
constexpr double kSupportPx = 1.0, kSupportRadii = 0.08;

// An edge's chroma is compared with the chroma kSideReachPx (at most kSideReachRadii radii) either
// side of it: past a JPEG's chroma, halved in resolution and smoothed back, which steps over about
// four pixels. Between them it is read every kChromaStepPx; sides whose chroma differs by less
// than kMinChromaStep [L*a*b* units] do not place an edge. The window is centred on its own
// crossing in kSettleRounds rounds; a crossing further than kMaxSettlePx from the fastest change
// of colour is another edge's.
constexpr double kSideReachPx = 3.0, kSideReachRadii = 0.5;
constexpr double kChromaStepPx = 0.25;
constexpr double kMinChromaStep = 4.0;
// A ball's side is white (the cue ball, a stripe's white) when its chroma is under
// kNeutralChroma and its lightness over kNeutralLightness [L*a*b* units].
constexpr double kNeutralChroma = 10.0, kNeutralLightness = 30.0;
constexpr int kSettleRounds = 3;
constexpr double kMaxSettlePx = 2.0;

// The peak of the parabola through samples i - 1, i, i + 1 of `rate` (a local maximum), in
// samples from i.
double ParabolaPeak(const std::vector<double>& rate, int i) {
  const double curvature = rate[i - 1] - 2 * rate[i] + rate[i + 1];
  const double offset = curvature < 0 ? 0.5 * (rate[i - 1] - rate[i + 1]) / curvature : 0.0;
  return std::clamp(offset, -1.0, 1.0);
}

// Where along the ray from `centre` in `direction` the chroma is half way between its values
// `reach` either side of `middle` [px from centre], the crossing nearest `middle`; none when
// the sides' chroma hardly differs, the inner side is not white, or a side is outside the image.
std::optional<double> ChromaCrossing(const LabImage& lab, const Eigen::Vector2d& centre,
                                     const Eigen::Vector2d& direction, double middle,
                                     double reach) {
  cv::Vec3f inside, beyond;
  if (!lab.At(centre + (middle - reach) * direction, &inside) ||
      !lab.At(centre + (middle + reach) * direction, &beyond)) {
    return std::nullopt;
  }
  const Eigen::Vector2d from(inside[1], inside[2]);
  const Eigen::Vector2d chroma_step = Eigen::Vector2d(beyond[1], beyond[2]) - from;
  if (chroma_step.norm() < kMinChromaStep) return std::nullopt;
  if (std::hypot(inside[1], inside[2]) > kNeutralChroma || inside[0] < kNeutralLightness) {
    return std::nullopt;
  }
  std::optional<double> nearest;
  double previous_share = 0.0;
  const int samples = static_cast<int>(2 * reach / kChromaStepPx);
  for (int i = 0; i <= samples; ++i) {
    const double s = middle - reach + i * kChromaStepPx;
    cv::Vec3f colour;
    lab.At(centre + s * direction, &colour);
    const double share =
        (Eigen::Vector2d(colour[1], colour[2]) - from).dot(chroma_step) / chroma_step.squaredNorm();
    if (i > 0 && (previous_share - 0.5) * (share - 0.5) <= 0 && share != previous_share) {
      const double crossing = s - kChromaStepPx * (share - 0.5) / (share - previous_share);
      if (!nearest || std::abs(crossing - middle) < std::abs(*nearest - middle)) {
        nearest = crossing;
      }
    }
    previous_share = share;
  }
  return nearest;
}

// The edge found at `place` [px from centre along `direction`], placed where the chroma is half
// way between the colours either side of it, when the chroma steps there; else `place`.
// On the inner limb of a ball off the camera's axis, lit from above, the camera sees the ball's
// shaded underside against its own shadow on the cloth: the lightness rises steadily from the
// outline inwards and hardly steps at it, and only the chroma does. The fastest change of colour
// lies inside the ball there, on its shading, once a JPEG has blurred the chroma, and the centre
// moves away from the axis: a scale of the positions about it (+0.087 % through the loop's JPEG),
// which an identification of the table reads as rolling resistance. A blurred step of chroma is
// still half way where the step was, and shading leaves a white ball's chroma where it was (none);
// a coloured ball's L*a*b* chroma falls with its lightness, so its half-way crossing is not its
// outline (on exact frames it moves the centre more than the shading did), and it keeps its
// fastest change, as does a change of lightness alone (a grey frame).
double SettledOnChroma(const LabImage& lab, const Eigen::Vector2d& centre,
                       const Eigen::Vector2d& direction, double place, double radius) {
  const double reach = std::min(kSideReachPx, kSideReachRadii * radius);
  double middle = place;
  for (int round = 0; round < kSettleRounds; ++round) {
    const std::optional<double> crossing = ChromaCrossing(lab, centre, direction, middle, reach);
    if (!crossing || std::abs(*crossing - place) > kMaxSettlePx) return place;
    middle = *crossing;
  }
  return middle;
}

Eigen::Vector2d RayDirection(int k) {
  const double angle = 2 * M_PI * k / kOutlineRays;
  return {std::cos(angle), std::sin(angle)};
}

// The outline judged on the rays in view: supporting_rays, seen_rays and largest_gap counted over
// the rays whose places on the circle `occluder` does not hide (a gap runs over the rays in view
// between two supporting ones), unless more than half the circle is beyond the occluder's line
// (its margin, which keeps the occluder's own edge from the fit, hides no part of the ball: a
// ball centred on the line is half seen, as a set's labels count it).
void CountSupportInView(const Occluder& occluder, BallOutline* outline) {
  Occluder line = occluder;
  line.margin_px = 0;
  int beyond_line = 0;
  for (int k = 0; k < kOutlineRays; ++k) {
    const Eigen::Vector2d place = outline->centre + outline->radius * RayDirection(k);
    outline->hidden[k] = occluder.Hides(place);
    beyond_line += line.Hides(place);
  }
  if (2 * beyond_line > kOutlineRays) outline->hidden.reset();
  const OutlineRays seen = ~outline->hidden;
  outline->seen_rays = static_cast<int>(seen.count());
  outline->supporting_rays = static_cast<int>((outline->supporting & seen).count());
  outline->largest_gap = 2 * M_PI;
  if (outline->supporting_rays == 0) return;
  // Around the circle from a supporting ray: each gap is one ray's angle more than the rays in
  // view without support between two supporting ones.
  int first = 0;
  while (!(outline->supporting[first] && seen[first])) ++first;
  int largest_run = 0, run = 0;
  for (int step = 1; step <= kOutlineRays; ++step) {
    const int k = (first + step) % kOutlineRays;
    if (!seen[k]) continue;
    if (outline->supporting[k]) {
      largest_run = std::max(largest_run, run);
      run = 0;
    } else {
      ++run;
    }
  }
  outline->largest_gap = 2 * M_PI * (largest_run + 1) / kOutlineRays;
}

// A ball at least half in view has its centre on this side of the occluder: a guess beyond it (a
// peak of the votes pulled onto the occluder's own straight edge) is moved back into view, to
// kInViewRadii radii from it, where the rays from it reach the ball's far edge.
Eigen::Vector2d InView(const Eigen::Vector2d& start, double radius, const Occluder& occluder) {
  const double limit = occluder.offset - occluder.margin_px - kInViewRadii * radius;
  const double beyond = occluder.normal.dot(start) - limit;
  return occluder.normal.squaredNorm() > 0 && beyond > 0 ? start - beyond * occluder.normal
                                                         : start;
}

// The places along each ray from `centre` where the colour changes fastest (frame pixels), and
// how fast; rays that leave the image have none, and `occluder` hides the places beyond it.
using RayEdges = std::vector<std::pair<Eigen::Vector2d, double>>;

std::array<RayEdges, kOutlineRays> EdgesAlongRays(const LabImage& lab,
                                                  const Eigen::Vector2d& centre, double radius,
                                                  double min_edge, const RaySampling& sampling,
                                                  const Occluder& occluder) {
  std::array<RayEdges, kOutlineRays> edges;
  const double step = sampling.step;
  const double from = (1.0 - sampling.range) * radius;
  const int samples = static_cast<int>(2 * sampling.range * radius / step) + 1;
  std::vector<cv::Vec3f> colour(samples);
  std::vector<double> rate(samples, 0.0);
  for (int k = 0; k < kOutlineRays; ++k) {
    const Eigen::Vector2d direction = RayDirection(k);
    bool inside = true;
    for (int i = 0; i < samples && inside; ++i) {
      inside = lab.At(centre + (from + i * step) * direction, &colour[i]);
    }
    if (!inside) continue;
    double largest = 0;
    for (int i = 1; i + 1 < samples; ++i) {
      const cv::Vec3f d = colour[i + 1] - colour[i - 1];
      rate[i] = std::sqrt(d.dot(d)) / (2 * step);
      largest = std::max(largest, rate[i]);
    }
    for (int i = 2; i + 2 < samples; ++i) {
      if (rate[i] < min_edge || rate[i] < kEdgeOfRayMax * largest || rate[i] < rate[i - 1] ||
          rate[i] < rate[i + 1]) {
        continue;
      }
      double place = from + (i + ParabolaPeak(rate, i)) * step;
      if (sampling.on_chroma) place = SettledOnChroma(lab, centre, direction, place, radius);
      const Eigen::Vector2d point = centre + place * direction;
      if (!occluder.Hides(point)) edges[k].push_back({point, rate[i]});
    }
  }
  return edges;
}

// The circle through the candidate of each ray nearest it, by IRLS from (centre, radius), with
// the radius pulled towards `expected`. False when too few rays have a candidate near it.
bool FitCircle(const std::array<RayEdges, kOutlineRays>& edges, double expected,
               double prior_rays, Eigen::Vector2d* centre, double* radius) {
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    std::vector<Eigen::Vector2d> points;
    std::vector<double> residuals;
    for (const RayEdges& ray : edges) {
      // The strongest edge within reach of the circle: a ball's outline against the cloth or
      // another ball changes the colour most; its shading, number and stripe less.
      double strongest = 0;
      const Eigen::Vector2d* chosen = nullptr;
      for (const auto& [point, rate] : ray) {
        const double distance = std::abs((point - *centre).norm() - *radius);
        if (distance < kCandidateReach * expected && rate > strongest) {
          strongest = rate;
          chosen = &point;
        }
      }
      if (chosen == nullptr) continue;
      points.push_back(*chosen);
      residuals.push_back((*chosen - *centre).norm() - *radius);
    }
    if (static_cast<int>(points.size()) < kMinCandidateRays) return false;
    std::vector<double> magnitudes(residuals.size());
    std::transform(residuals.begin(), residuals.end(), magnitudes.begin(),
                   [](double r) { return std::abs(r); });
    std::nth_element(magnitudes.begin(), magnitudes.begin() + magnitudes.size() / 2,
                     magnitudes.end());
    const double scale = std::max(kMinScalePx, 1.4826 * magnitudes[magnitudes.size() / 2]);
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double u = residuals[i] / (kTukey * scale);
      if (std::abs(u) >= 1) continue;
      const double weight = (1 - u * u) * (1 - u * u);
      const Eigen::Vector2d d = points[i] - *centre;
      const double n = d.norm();
      if (n < 1e-9) continue;
      const Eigen::Vector3d j(-d.x() / n, -d.y() / n, -1.0);
      normal += weight * j * j.transpose();
      gradient += weight * j * residuals[i];
    }
    normal(2, 2) += prior_rays;
    gradient(2) += prior_rays * (*radius - expected);
    const Eigen::Vector3d step = -normal.ldlt().solve(gradient);
    if (!step.allFinite()) return false;
    *centre += step.head<2>();
    *radius += step.z();
    if (step.norm() < kStepPx) break;
  }
  return true;
}

// How the fitted circle is supported: rays with an edge of at least `min_edge` within a band of
// it (the edges of the last round, cast from about the fitted centre).
void MeasureSupport(const std::array<RayEdges, kOutlineRays>& edges, double expected,
                    const Occluder& occluder, BallOutline* outline) {
  const double band = std::max(kSupportPx, kSupportRadii * expected);
  double strength = 0;
  for (int k = 0; k < kOutlineRays; ++k) {
    double best = 0;
    for (const auto& [point, rate] : edges[k]) {
      if (std::abs((point - outline->centre).norm() - outline->radius) <= band) {
        best = std::max(best, rate);
      }
    }
    outline->supporting[k] = best > 0;
    strength += best;
  }
  const std::size_t supporting = outline->supporting.count();
  outline->edge_strength = supporting > 0 ? strength / supporting : 0.0;
  CountSupportInView(occluder, outline);
}

}  // namespace

cv::Rect OutlineWindow(const Eigen::Vector2d& start, double radius) {
  const int half = static_cast<int>(std::ceil(kWindowRadii * radius)) + kWindowMarginPx;
  return {static_cast<int>(std::lround(start.x())) - half,
          static_cast<int>(std::lround(start.y())) - half, 2 * half + 1, 2 * half + 1};
}

std::optional<BallOutline> FitBallOutline(const LabImage& lab, const Eigen::Vector2d& start,
                                          double radius, double min_edge,
                                          const Occluder& occluder) {
  if (!(radius > 0)) return std::nullopt;
  const Eigen::Vector2d from = InView(start, radius, occluder);
  Eigen::Vector2d centre = from;
  double fitted = radius;
  std::array<RayEdges, kOutlineRays> edges;
  for (const RaySampling& sampling : kRounds) {
    edges = EdgesAlongRays(lab, centre, radius, min_edge, sampling, occluder);
    if (!FitCircle(edges, radius, sampling.prior_rays, &centre, &fitted)) return std::nullopt;
    if ((centre - from).norm() > kMaxShiftRadii * radius ||
        std::abs(fitted - radius) > kMaxRadiusChange * radius) {
      return std::nullopt;
    }
  }
  BallOutline outline;
  outline.centre = centre;
  outline.radius = fitted;
  MeasureSupport(edges, radius, occluder, &outline);
  return outline;
}

Eigen::Vector2d CentreOnChroma(const LabImage& lab, const Eigen::Vector2d& centre, double radius,
                               double min_edge, const Occluder& occluder) {
  Eigen::Vector2d placed = centre;
  double fitted = radius;
  const std::array<RayEdges, kOutlineRays> edges =
      EdgesAlongRays(lab, centre, radius, min_edge, kChromaRound, occluder);
  const bool fitted_ok = FitCircle(edges, radius, kChromaRound.prior_rays, &placed, &fitted);
  return fitted_ok && (placed - centre).norm() <= kMaxSettlePx ? placed : centre;
}

}  // namespace billiard::estimator
