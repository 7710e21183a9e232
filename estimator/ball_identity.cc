#include "estimator/ball_identity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace billiard::estimator {

namespace {

// The disc a ball's colours are read from, in fitted radii: inside the blur of the outline and
// the darkest shading at the rim.
constexpr double kDiscRadii = 0.75;
// A pixel is grey when its chroma (sqrt(a*^2 + b*^2)) is below kGreyChroma; grey and at least
// kWhiteLightness (after the exposure is set, below) it is white, grey and at most
// kBlackLightness black.
constexpr double kGreyChroma = 16.0;
constexpr double kWhiteLightness = 65.0, kBlackLightness = 30.0;
// The white balance's reference: among the balls whose median L* is at least kBrightBalls of the
// brightest's, the least coloured, if its median chroma is below kMaxCueChroma; its brighter half
// is made grey of lightness kCueLightness.
constexpr double kBrightBalls = 0.8;
constexpr double kMaxCueChroma = 40.0;
constexpr double kCueLightness = 90.0;
// Shares of a ball's disc: the cue ball is at least kCueWhite white with at most kCueColour
// coloured; a black ball at least kBlackShare black; a pool ball at least kStripeWhite white a
// stripe, its certainty growing over kStripeMargin either side.
constexpr double kCueWhite = 0.6, kCueColour = 0.2;
constexpr double kBlackShare = 0.5;
constexpr double kStripeWhite = 0.3, kStripeMargin = 0.15;
// Colour distance (ColourDistance): hue fully, chroma and L* weighted down.
constexpr double kChromaWeight = 0.3, kLightnessWeight = 0.3;

struct Colour {
  BallClass ball_class;
  cv::Vec3b srgb;  // R, G, B under white light
};

// Approximate colours of the balls (their sRGB under white light, read from manufacturers'
// product pictures: Aramith pool and snooker sets, carom balls); the classifier compares hues
// more than lightness, so a few per cent either way changes little.
const std::vector<Colour>& ColoursOf(BallSet set) {
  static const std::vector<Colour> kPool = {
      {PoolBall(1), {250, 195, 10}},  {PoolBall(2), {20, 50, 160}},
      {PoolBall(3), {215, 30, 30}},   {PoolBall(4), {85, 35, 125}},
      {PoolBall(5), {250, 110, 10}},  {PoolBall(6), {10, 110, 60}},
      {PoolBall(7), {125, 25, 35}}};
  static const std::vector<Colour> kSnooker = {
      {BallClass::kRed, {200, 20, 20}},   {BallClass::kYellow, {250, 210, 10}},
      {BallClass::kGreen, {10, 100, 50}}, {BallClass::kBrown, {110, 60, 30}},
      {BallClass::kBlue, {10, 70, 180}},  {BallClass::kPink, {245, 150, 170}}};
  static const std::vector<Colour> kCarom = {{BallClass::kRed, {210, 30, 30}},
                                             {BallClass::kYellow, {250, 210, 20}}};
  switch (set) {
    case BallSet::kSnooker:
      return kSnooker;
    case BallSet::kCarom:
      return kCarom;
    case BallSet::kPool:
      break;
  }
  return kPool;
}

cv::Vec3f LabOfSrgb(const cv::Vec3b& srgb) {
  const cv::Mat pixel(1, 1, CV_32FC3,
                      cv::Scalar(srgb[2] / 255.0, srgb[1] / 255.0, srgb[0] / 255.0));  // BGR
  cv::Mat lab;
  cv::cvtColor(pixel, lab, cv::COLOR_BGR2Lab);
  return lab.at<cv::Vec3f>(0, 0);
}

double Chroma(const cv::Vec3f& lab) { return std::hypot(lab[1], lab[2]); }

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

// A ball's disc pixels (BGR, 0..1).
std::vector<cv::Vec3f> DiscPixels(const cv::Mat& bgr, const BallDetection& ball) {
  std::vector<cv::Vec3f> pixels;
  const double reach = kDiscRadii * ball.radius_px;
  const int x0 = std::max(0, static_cast<int>(std::floor(ball.pixel.x() - reach)));
  const int x1 = std::min(bgr.cols - 1, static_cast<int>(std::ceil(ball.pixel.x() + reach)));
  const int y0 = std::max(0, static_cast<int>(std::floor(ball.pixel.y() - reach)));
  const int y1 = std::min(bgr.rows - 1, static_cast<int>(std::ceil(ball.pixel.y() + reach)));
  for (int y = y0; y <= y1; ++y) {
    const auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = x0; x <= x1; ++x) {
      if (std::hypot(x - ball.pixel.x(), y - ball.pixel.y()) > reach) continue;
      pixels.emplace_back(row[x][0] / 255.0f, row[x][1] / 255.0f, row[x][2] / 255.0f);
    }
  }
  return pixels;
}

std::vector<cv::Vec3f> ToLab(const std::vector<cv::Vec3f>& bgr, const cv::Vec3f& gain) {
  if (bgr.empty()) return {};
  cv::Mat pixels(static_cast<int>(bgr.size()), 1, CV_32FC3);
  for (std::size_t i = 0; i < bgr.size(); ++i) {
    const cv::Vec3f& p = bgr[i];
    pixels.at<cv::Vec3f>(static_cast<int>(i)) =
        cv::Vec3f(std::min(1.0f, p[0] * gain[0]), std::min(1.0f, p[1] * gain[1]),
                  std::min(1.0f, p[2] * gain[2]));
  }
  cv::Mat lab;
  cv::cvtColor(pixels, lab, cv::COLOR_BGR2Lab);
  return std::vector<cv::Vec3f>(lab.begin<cv::Vec3f>(), lab.end<cv::Vec3f>());
}

// The per-channel gains that make the frame's cue ball grey at kCueLightness, or, without one,
// that bring its brightest ball pixels there. The cue ball is the least coloured of the bright
// balls (those whose median L* is within kBrightBalls of the brightest ball's): under a tinted
// light it takes the light's colour, but less of it than any coloured ball has.
cv::Vec3f WhiteBalance(const std::vector<std::vector<cv::Vec3f>>& discs) {
  std::vector<std::vector<cv::Vec3f>> labs;
  std::vector<double> lightness, chroma;
  for (const auto& disc : discs) {
    labs.push_back(ToLab(disc, {1, 1, 1}));
    std::vector<float> l, c;
    for (const auto& p : labs.back()) {
      l.push_back(p[0]);
      c.push_back(static_cast<float>(Chroma(p)));
    }
    lightness.push_back(l.empty() ? 0.0 : Median(l));
    chroma.push_back(c.empty() ? HUGE_VAL : Median(c));
  }
  if (discs.empty()) return {1, 1, 1};
  const double brightest = *std::max_element(lightness.begin(), lightness.end());
  int cue = -1;
  for (std::size_t b = 0; b < discs.size(); ++b) {
    if (lightness[b] < kBrightBalls * brightest || chroma[b] > kMaxCueChroma) continue;
    if (cue < 0 || chroma[b] < chroma[cue]) cue = static_cast<int>(b);
  }
  // The reference: the cue ball's brighter half, or the brightest ball's.
  const int reference = cue >= 0 ? cue
                                 : static_cast<int>(std::max_element(lightness.begin(),
                                                                     lightness.end()) -
                                                    lightness.begin());
  cv::Vec3d mean(0, 0, 0);
  int count = 0;
  for (std::size_t i = 0; i < discs[reference].size(); ++i) {
    if (labs[reference][i][0] < lightness[reference]) continue;
    mean += cv::Vec3d(discs[reference][i]);
    ++count;
  }
  if (count == 0) return {1, 1, 1};
  mean /= count;
  cv::Mat target(1, 1, CV_32FC3, cv::Scalar(kCueLightness, 0, 0)), grey;
  cv::cvtColor(target, grey, cv::COLOR_Lab2BGR);
  const float level = grey.at<cv::Vec3f>(0, 0)[0];
  cv::Vec3f gain;
  for (int c = 0; c < 3; ++c) gain[c] = static_cast<float>(level / std::max(1e-3, mean[c]));
  if (cue < 0) {
    // Without a white reference, the brightness only: the colours' balance is the camera's.
    const float g = (gain[0] + gain[1] + gain[2]) / 3;
    gain = {g, g, g};
  }
  return gain;
}

double Ramp(double x, double from, double width) {
  return std::clamp((x - from) / width, 0.0, 1.0);
}

BallIdentity Classify(const std::vector<cv::Vec3f>& lab, BallSet set) {
  if (lab.empty()) return {};
  int white = 0, black = 0;
  std::vector<float> a, b, l;
  for (const auto& p : lab) {
    const bool grey = Chroma(p) < kGreyChroma;
    if (grey && p[0] >= kWhiteLightness) {
      ++white;
    } else if (grey && p[0] <= kBlackLightness) {
      ++black;
    } else if (!grey) {
      a.push_back(p[1]);
      b.push_back(p[2]);
      l.push_back(p[0]);
    }
  }
  const double n = static_cast<double>(lab.size());
  const double white_share = white / n, black_share = black / n, colour_share = a.size() / n;
  if (white_share >= kCueWhite && colour_share <= kCueColour) {
    return {BallClass::kCue, Ramp(white_share, kCueWhite - 0.1, 0.3) *
                                 (1.0 - Ramp(colour_share, 0.0, 2 * kCueColour))};
  }
  if (black_share >= kBlackShare && set != BallSet::kCarom) {
    return {set == BallSet::kPool ? PoolBall(8) : BallClass::kBlack,
            Ramp(black_share, kBlackShare - 0.1, 0.3)};
  }
  if (a.empty()) return {};
  const double ma = Median(a), mb = Median(b), ml = Median(l);
  const auto& colours = ColoursOf(set);
  double nearest = HUGE_VAL, second = HUGE_VAL;
  BallClass best = BallClass::kUnknown;
  for (const Colour& c : colours) {
    const double d = ColourDistance({static_cast<float>(ml), static_cast<float>(ma),
                                     static_cast<float>(mb)},
                                    LabOfSrgb(c.srgb));
    if (d < nearest) {
      second = nearest;
      nearest = d;
      best = c.ball_class;
    } else if (d < second) {
      second = d;
    }
  }
  double confidence = colours.size() > 1 ? 1.0 - nearest / std::max(second, 1e-9) : 1.0;
  if (set == BallSet::kPool) {
    const bool stripe = white_share >= kStripeWhite;
    confidence *= Ramp(std::abs(white_share - kStripeWhite), 0.0, kStripeMargin);
    if (stripe) best = PoolBall(static_cast<int>(best) + 8);
  }
  return {best, std::clamp(confidence, 0.0, 1.0)};
}

}  // namespace

std::vector<BallIdentity> IdentifyBalls(const cv::Mat& bgr, const std::vector<BallDetection>& balls,
                                        BallSet set) {
  std::vector<std::vector<cv::Vec3f>> discs;
  for (const BallDetection& ball : balls) discs.push_back(DiscPixels(bgr, ball));
  const cv::Vec3f gain = WhiteBalance(discs);
  std::vector<BallIdentity> identities;
  for (const auto& disc : discs) identities.push_back(Classify(ToLab(disc, gain), set));
  return identities;
}

}  // namespace billiard::estimator
