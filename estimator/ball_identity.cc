#include "estimator/ball_identity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "estimator/assignment.h"
#include "estimator/ball_pixels.h"
#include "estimator/ball_features.h"
#include "estimator/identity_classifier.h"

namespace billiard::estimator {

namespace {

// The disc a ball's colours are read from, in fitted radii: inside the blur of the outline and
// the darkest shading at the rim.
constexpr double kDiscRadii = 0.75;
// The disc a ball's plain share is read from, in fitted radii: nearly the whole ball. A stripe
// turned with its band to the camera shows its white caps only near the limb, foreshortened and in
// shade, outside kDiscRadii; a solid shows its colour there too (the cloth beyond the outline's
// blur is coloured, or dark and saturated in the ball's shadow).
constexpr double kLimbRadii = 0.9;
// The white balance's reference: among the balls whose median L* is at least kBrightBalls of the
// brightest's, the least coloured, if its median chroma is below kMaxCueChroma; its brighter half
// is made grey of lightness kCueLightness.
constexpr double kBrightBalls = 0.8;
constexpr double kMaxCueChroma = 40.0;
constexpr double kCueLightness = 90.0;
// A frame without a cue ball is balanced on its balls' white and grey where it shows at least
// kMinWhitePixels of them (WhitePixelsMean).
constexpr std::size_t kMinWhitePixels = 12;
// A channel at kClippedLevel (of 1) or more is clipped.
constexpr float kClippedLevel = 250.0f / 255.0f;
// The shares of a ball's disc that make it the cue ball, a black ball or a stripe are parameters
// (identity_parameters.h); a stripe's plain share is read within kLimbRadii (its white caps, lit or
// in shade, facing the camera or at the limb).
// Colour distance (ColourDistance): hue fully, chroma and L* weighted down.
constexpr double kChromaWeight = 0.3, kLightnessWeight = 0.3;
// The classes are given all at once, the rack's count of each respected (the Hungarian method,
// assignment.h): a share on the wrong side of its threshold costs one per kShareMargin, a colour
// one per kColourUnit of ColourDistance (about the distance between neighbouring hues of the
// sets, red and orange); a ball without coloured pixels costs kNoColourCost for a coloured class.
// A ball none fits better than kUnknownCost (times its detection's score) stays unknown, and so
// do the balls beyond the rack's count. The confidence is 1 - (cost + kCostFloor) / (cost + margin
// + kCostFloor), where the margin is what the whole assignment would lose were the ball not of its
// class (ClassMargin).
constexpr double kShareMargin = 0.15;
constexpr double kColourUnit = 30.0;
constexpr double kNoColourCost = 3.0;
constexpr double kUnknownCost = 4.0;
constexpr double kForbiddenCost = 1e6;
constexpr double kCostFloor = 0.1;


// How different a ball's colour is from a reference, hue first: the hue angle's difference
// (CIE LCh) as an arc at the mean chroma, plus the chroma's and lightness's differences weighted
// down by kChromaWeight and kLightnessWeight (exposure and shading change both, washing a yellow
// out to a pale one and darkening a red, but leave the hue).
double ColourDistance(const cv::Vec3f& lab, const cv::Vec3f& reference) {
  const double c1 = Chroma(lab), c2 = Chroma(reference);
  double dh = std::abs(std::atan2(lab[2], lab[1]) - std::atan2(reference[2], reference[1]));
  if (dh > M_PI) dh = 2 * M_PI - dh;
  return std::sqrt(std::pow(dh * 0.5 * (c1 + c2), 2) + std::pow(kChromaWeight * (c1 - c2), 2) +
                   std::pow(kLightnessWeight * (lab[0] - reference[0]), 2));
}

double Median(std::vector<float>& values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// The per-channel median of pixels (L*a*b*), of which there is at least one.
cv::Vec3f MedianColour(const std::vector<cv::Vec3f>& lab) {
  cv::Vec3f median;
  std::vector<float> channel(lab.size());
  for (int c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < lab.size(); ++i) channel[i] = lab[i][c];
    median[c] = static_cast<float>(Median(channel));
  }
  return median;
}

// A ball's pixels (BGR, 0..1) from `inner` to `outer` of its fitted radius.
std::vector<cv::Vec3f> RingPixels(const cv::Mat& bgr, const BallDetection& ball, double inner,
                                  double outer) {
  std::vector<cv::Vec3f> pixels;
  const double from = inner * ball.radius_px;
  ForEachPixelWithin(bgr, ball, outer, [&](const cv::Vec3f& p, double r) {
    if (r >= from) pixels.push_back(p);
  });
  return pixels;
}

// A ball's pixels (BGR, 0..1) in one pass: its disc, within kDiscRadii, and the ring beyond it
// out to kLimbRadii.
struct BallPixels {
  std::vector<cv::Vec3f> disc, limb_ring;
};

BallPixels ReadBall(const cv::Mat& bgr, const BallDetection& ball) {
  BallPixels pixels;
  const double disc = kDiscRadii * ball.radius_px;
  ForEachPixelWithin(bgr, ball, kLimbRadii, [&](const cv::Vec3f& p, double r) {
    (r <= disc ? pixels.disc : pixels.limb_ring).push_back(p);
  });
  return pixels;
}

// A frame without a cue ball still shows white and grey: the caps of its stripes, the circles of
// its numbers, the highlights of its glossy balls. Their mean colour (BGR) is the light's: the
// pixels of every ball that are bright (kWhiteLightness) and not clipped, of chroma below
// kMaxCueChroma (as a tinted light leaves a white), the less saturated half of them; none when
// fewer than kMinWhitePixels.
std::optional<cv::Vec3d> WhitePixelsMean(const std::vector<BallPixels>& balls,
                                         const std::vector<std::vector<cv::Vec3f>>& labs) {
  std::vector<std::pair<double, cv::Vec3f>> candidates;  // (saturation, BGR)
  for (std::size_t b = 0; b < balls.size(); ++b) {
    for (std::size_t i = 0; i < balls[b].disc.size(); ++i) {
      const cv::Vec3f& p = balls[b].disc[i];
      const cv::Vec3f& lab = labs[b][i];
      if (lab[0] < kWhiteLightness || Chroma(lab) > kMaxCueChroma ||
          std::max({p[0], p[1], p[2]}) >= kClippedLevel) {
        continue;
      }
      candidates.push_back({Chroma(lab) / lab[0], p});
    }
  }
  if (candidates.size() < 2 * kMinWhitePixels) return std::nullopt;
  const auto half = candidates.begin() + candidates.size() / 2;
  std::nth_element(candidates.begin(), half, candidates.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  cv::Vec3d mean(0, 0, 0);
  for (auto it = candidates.begin(); it != half; ++it) mean += cv::Vec3d(it->second);
  return mean / static_cast<double>(half - candidates.begin());
}

// The per-channel gains that make the frame's cue ball grey at kCueLightness, or, without one,
// its other balls' white and grey (WhitePixelsMean), else that bring its brightest ball pixels
// there. The cue ball is the least coloured of the bright balls (those whose median L* is within
// kBrightBalls of the brightest ball's): under a tinted light it takes the light's colour, but
// less of it than any coloured ball has.
cv::Vec3f WhiteBalance(const std::vector<BallPixels>& balls) {
  std::vector<std::vector<cv::Vec3f>> labs;
  std::vector<double> lightness, chroma;
  for (const BallPixels& ball : balls) {
    labs.push_back(ToLab(ball.disc, {1, 1, 1}));
    std::vector<float> l, c;
    for (const auto& p : labs.back()) {
      l.push_back(p[0]);
      c.push_back(static_cast<float>(Chroma(p)));
    }
    lightness.push_back(l.empty() ? 0.0 : Median(l));
    chroma.push_back(c.empty() ? HUGE_VAL : Median(c));
  }
  if (balls.empty()) return {1, 1, 1};
  const double brightest = *std::max_element(lightness.begin(), lightness.end());
  int cue = -1;
  for (std::size_t b = 0; b < balls.size(); ++b) {
    if (lightness[b] < kBrightBalls * brightest || chroma[b] > kMaxCueChroma) continue;
    if (cue < 0 || chroma[b] < chroma[cue]) cue = static_cast<int>(b);
  }
  // The reference: the cue ball's brighter half, or the brightest ball's.
  const int reference =
      cue >= 0 ? cue
               : static_cast<int>(std::max_element(lightness.begin(), lightness.end()) -
                                  lightness.begin());
  // Its pixels with a channel at the sensor's limit tell the limit, not the light's colour: left
  // out, unless there are no others.
  cv::Vec3d mean(0, 0, 0);
  int count = 0;
  for (const bool with_clipped : {false, true}) {
    const std::vector<cv::Vec3f>& disc = balls[reference].disc;
    for (std::size_t i = 0; i < disc.size(); ++i) {
      const cv::Vec3f& p = disc[i];
      const bool clipped = std::max({p[0], p[1], p[2]}) >= kClippedLevel;
      if (labs[reference][i][0] < lightness[reference] || (clipped && !with_clipped)) continue;
      mean += cv::Vec3d(p);
      ++count;
    }
    if (count > 0) break;
  }
  if (count == 0) return {1, 1, 1};
  mean /= count;
  cv::Mat target(1, 1, CV_32FC3, cv::Scalar(kCueLightness, 0, 0)), grey;
  cv::cvtColor(target, grey, cv::COLOR_Lab2BGR);
  const float level = grey.at<cv::Vec3f>(0, 0)[0];
  cv::Vec3f gain;
  for (int c = 0; c < 3; ++c) gain[c] = static_cast<float>(level / std::max(1e-3, mean[c]));
  if (cue >= 0) return gain;
  // Without a cue ball, the white and grey the other balls show (a stripe's caps, the numbers'
  // circles, the highlights, which are the light's colour: Lee 1986), else the brightness only.
  if (const auto white = WhitePixelsMean(balls, labs)) {
    for (int c = 0; c < 3; ++c) gain[c] = static_cast<float>(level / std::max(1e-3, (*white)[c]));
    return gain;
  }
  const float g = (gain[0] + gain[1] + gain[2]) / 3;
  return {g, g, g};
}

std::ptrdiff_t PlainCount(const std::vector<cv::Vec3f>& lab) {
  return std::count_if(lab.begin(), lab.end(), Plain);
}

// `disc` and `limb_ring`: the ball's pixels (L*a*b*) within kDiscRadii and from there to
// kLimbRadii.
BallLook Look(const std::vector<cv::Vec3f>& disc, const std::vector<cv::Vec3f>& limb_ring) {
  BallLook look;
  if (disc.empty()) return look;
  look.seen = true;
  int white = 0, black = 0;
  std::vector<cv::Vec3f> coloured;
  for (const auto& p : disc) {
    const bool grey = Chroma(p) < kGreyChroma;
    white += grey && p[0] >= kWhiteLightness;
    black += grey && p[0] <= kBlackLightness;
    if (!Plain(p)) coloured.push_back(p);
  }
  const double n = static_cast<double>(disc.size());
  look.white = white / n;
  look.black = black / n;
  look.plain = static_cast<double>(PlainCount(disc) + PlainCount(limb_ring)) /
               (disc.size() + limb_ring.size());
  look.colour = coloured.size() / n;
  if (!coloured.empty()) look.disc_colour = MedianColour(coloured);
  return look;
}

// A stripe seen cap on (its axis toward the camera) shows its white cap over nearly all of its
// disc, out to about sin 60 = 0.87 of its radius for a band of +-30 degrees of latitude, and its
// outline is fitted to the cap's edge, the sharpest; its band is then a ring just outside the
// outline, out to about 1.15 of it. The colour of that ring (out to kBandRadii) is read with the
// cloth left out: the pixels within kColourUnit of the cloth's median around the ball
// (kClothRing, a ring clear of the ball and of its shadow), and the plain ones (the cap's blur, the
// shadow's grey), if they leave kBandShare of the ring. A ball without colour in its disc and with
// a stripe's plain share takes it (JudgedColour). A cue ball alone has only cloth and shadow
// around it, so nothing is read; one touching a coloured ball may read that ball's colour, which
// costs it nothing as the cue ball (its cost is in shares, not hues) and only matters against
// another white ball, a stripe cap on.
constexpr double kBandRadii = 1.25;
constexpr double kClothRing[2] = {1.5, 2.0};
constexpr double kBandShare = 0.15;

void ReadBandBeyondCap(const cv::Mat& bgr, const BallDetection& ball, const cv::Vec3f& gain,
                       BallLook* look) {
  if (!look->seen) return;
  const auto cloth = ToLab(RingPixels(bgr, ball, kClothRing[0], kClothRing[1]), gain);
  if (cloth.empty()) return;
  const cv::Vec3f cloth_colour = MedianColour(cloth);
  std::vector<cv::Vec3f> coloured;
  const auto band = ToLab(RingPixels(bgr, ball, 1.0, kBandRadii), gain);
  for (const auto& p : band) {
    if (!Plain(p) && ColourDistance(p, cloth_colour) >= kColourUnit) coloured.push_back(p);
  }
  if (coloured.empty() || coloured.size() < kBandShare * band.size()) return;
  look->band_colour = MedianColour(coloured);
}

// What leaving a ball unnamed costs: kUnknownCost for a sure ball, less for an outline the
// detector doubts (its score), so that the rack's one of each number goes to the sure balls
// before a hand or a shadow takes it.
double UnknownCost(const BallDetection& ball) {
  return kUnknownCost * std::clamp(ball.score, 0.0, 1.0);
}

// How many balls of each class a set holds.
std::vector<std::pair<BallClass, int>> ClassesOf(BallSet set) {
  std::vector<std::pair<BallClass, int>> classes;
  for (const BallClass c : ClassesIn(set)) classes.push_back({c, CountIn(set, c)});
  return classes;
}

// How far a share is on the wrong side of a threshold, in units of `margin`: 0 on the right side.
double Beyond(double share, double threshold, double margin) {
  return std::max(0.0, share - threshold) / margin;
}

// The cost of calling a ball of this look `ball_class` of `set`: how far each of its shares is on
// the wrong side of the class's threshold (the parameters' cue_white, cue_colour, black_share,
// stripe_plain), in kShareMargin, plus its colour's distance from the class's nearest colour
// (ColourDistance) in kColourUnit.
double Cost(const BallLook& look, BallClass ball_class, BallSet set, const IdentityParameters& p) {
  if (ball_class == BallClass::kCue) {
    return Beyond(p.cue_white, look.white, kShareMargin) +
           Beyond(look.colour, p.cue_colour, kShareMargin);
  }
  const bool black_ball =
      ball_class == BallClass::kBlack || (set == BallSet::kPool && ball_class == PoolBall(8));
  if (black_ball) return Beyond(p.black_share, look.black, kShareMargin);
  // A coloured ball: some colour, not mostly black, its hue that of its class.
  double cost = Beyond(p.cue_colour, look.colour, kShareMargin) +
                Beyond(look.black, p.black_share, kShareMargin);
  if (set == BallSet::kPool) {
    const bool stripe = static_cast<int>(ball_class) > 8;
    cost += stripe ? Beyond(p.stripe_plain, look.plain, kShareMargin)
                   : Beyond(look.plain, p.stripe_plain, kShareMargin);
  } else {
    cost += Beyond(look.white, p.cue_white, kShareMargin);
  }
  const std::optional<cv::Vec3f> colour = JudgedColour(look, p);
  if (!colour) return cost + kNoColourCost;
  const BallClass colour_class = ColourClassOf(ball_class, set);
  const BallSet table = ColourTableOf(set);
  double distance = HUGE_VAL;  // to the nearest of the class's colours
  for (const ColourPrototype& c : p.colours) {
    if (c.table == table && c.ball_class == colour_class) {
      distance = std::min(distance, ColourDistance(*colour, c.lab));
    }
  }
  return cost + (distance < HUGE_VAL ? distance / kColourUnit : kNoColourCost);
}

// The cost of each class of ClassesIn(set) for a ball of this look: the parameters' classifier's
// where it knows the set, else Cost's; kForbiddenCost each for a ball not in the frame.
std::vector<double> ClassCosts(const BallLook& look, BallSet set, const IdentityParameters& p) {
  const std::vector<BallClass> classes = ClassesIn(set);
  if (!look.seen) return std::vector<double>(classes.size(), kForbiddenCost);
  if (p.classifier && p.classifier->Knows(set)) return p.classifier->ClassCosts(look.features, set);
  std::vector<double> costs;
  for (const BallClass c : classes) costs.push_back(Cost(look, c, set, p));
  return costs;
}

double TotalCost(const Eigen::MatrixXd& cost, const std::vector<int>& assigned) {
  double total = 0;
  for (int i = 0; i < cost.rows(); ++i) {
    if (assigned[i] >= 0) total += cost(i, assigned[i]);
  }
  return total;
}

// How much more the best assignment costs when `ball` may not take any of the slots of
// `ball_class` (whose class is `slots`'): its next best class, unless a ball given that class is
// moved, or the rack's count of it lets another ball take this one's (two balls alike, one
// slot). A rack has one of each number: the 11 whose stripe reads pale red is sure where the 3 is
// plainly a solid, unsure where the 3 is not on the table.
double ClassMargin(const Eigen::MatrixXd& cost, const std::vector<BallClass>& slots, int ball,
                   BallClass ball_class, double best_total) {
  Eigen::MatrixXd without = cost;
  for (std::size_t s = 0; s < slots.size(); ++s) {
    if (slots[s] == ball_class) without(ball, static_cast<int>(s)) = kForbiddenCost;
  }
  return std::max(
      0.0, TotalCost(without, AssignMinimumCost(without, kForbiddenCost)) - best_total);
}

}  // namespace

std::optional<cv::Vec3f> JudgedColour(const BallLook& look, const IdentityParameters& parameters) {
  const bool cap_on = look.band_colour && look.colour < parameters.cue_colour &&
                      look.plain >= parameters.stripe_plain;
  return cap_on ? look.band_colour : look.disc_colour;
}

std::vector<BallLook> LookAtBalls(const cv::Mat& bgr, const std::vector<BallDetection>& balls,
                                  BallSet set) {
  std::vector<BallPixels> pixels;
  for (const BallDetection& ball : balls) pixels.push_back(ReadBall(bgr, ball));
  const cv::Vec3f gain = WhiteBalance(pixels);
  std::vector<BallLook> looks;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    looks.push_back(Look(ToLab(pixels[i].disc, gain), ToLab(pixels[i].limb_ring, gain)));
    looks.back().features = BallFeatures(bgr, balls[i], gain);
  }
  if (set == BallSet::kPool) {
    for (std::size_t i = 0; i < balls.size(); ++i) ReadBandBeyondCap(bgr, balls[i], gain, &looks[i]);
  }
  return looks;
}

std::vector<BallIdentity> NameBalls(const std::vector<BallLook>& looks,
                                    const std::vector<BallDetection>& balls, BallSet set,
                                    const IdentityParameters& parameters) {
  // The rack holds so many of each class: one slot per ball of it, and for every ball a slot
  // "unknown" at kUnknownCost, which takes the balls beyond the rack's count (a false detection,
  // a ball of another set) and those no class fits.
  const auto classes = ClassesOf(set);
  std::vector<BallClass> slots;
  for (const auto& [ball_class, count] : classes) slots.insert(slots.end(), count, ball_class);
  const int n = static_cast<int>(balls.size());
  const int known = static_cast<int>(slots.size());
  Eigen::MatrixXd cost(n, known + n);
  for (int i = 0; i < n; ++i) {
    const std::vector<double> class_cost = ClassCosts(looks[i], set, parameters);
    int slot = 0;
    for (std::size_t c = 0; c < classes.size(); ++c) {
      for (int k = 0; k < classes[c].second; ++k) cost(i, slot++) = class_cost[c];
    }
    const double unknown = UnknownCost(balls[i]);
    for (int j = 0; j < n; ++j) cost(i, known + j) = looks[i].seen ? unknown : 0.0;
  }
  const std::vector<int> assigned = AssignMinimumCost(cost, kForbiddenCost);
  const double best_total = TotalCost(cost, assigned);
  std::vector<BallIdentity> identities(balls.size());
  for (int i = 0; i < n; ++i) {
    if (assigned[i] < 0 || assigned[i] >= known) continue;
    const BallClass ball_class = slots[assigned[i]];
    const double given = cost(i, assigned[i]);
    const double other = given + ClassMargin(cost, slots, i, ball_class, best_total);
    identities[i] = {ball_class,
                     std::clamp(1.0 - (given + kCostFloor) / (other + kCostFloor), 0.0, 1.0)};
  }
  return identities;
}

std::vector<BallIdentity> IdentifyBalls(const cv::Mat& bgr, const std::vector<BallDetection>& balls,
                                        BallSet set, const IdentityParameters& parameters) {
  return NameBalls(LookAtBalls(bgr, balls, set), balls, set, parameters);
}

}  // namespace billiard::estimator
