#include "sim/shot_fit/correlation_time.h"

#include <gtest/gtest.h>

#include <random>

namespace billiard::shot_fit {
namespace {

// A shot of one ball per series, every series' samples at 0, 1, 2, ... s.
TrackedShot ShotOf(const std::vector<std::size_t>& samples) {
  TrackedShot shot;
  for (std::size_t n : samples) {
    TrackedBall b;
    for (std::size_t i = 0; i < n; ++i) {
      b.t.push_back(static_cast<double>(i));
      b.position.push_back(Eigen::Vector2d::Zero());
    }
    shot.balls.push_back(b);
  }
  return shot;
}

// The products pair samples of one ball and one coordinate only (residuals x, y per sample,
// ball after ball), and the horizon leaves the later samples out.
TEST(LaggedProducts, PairSamplesOfOneBallAndOneCoordinate) {
  const TrackedShot shot = ShotOf({3, 2});
  //                               ball 0: x0 y0 x1 y1 x2 y2       ball 1: x0 y0 x1 y1
  const std::vector<double> r = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  const std::vector<double> lagged = LaggedProducts(shot, 10.0, r);
  ASSERT_EQ(lagged.size(), static_cast<std::size_t>(kMaxLag + 1));
  EXPECT_EQ(lagged[0], 1 + 4 + 9 + 16 + 25 + 36 + 49 + 64 + 81 + 100);
  EXPECT_EQ(lagged[1], 1 * 3 + 3 * 5 + 2 * 4 + 4 * 6 + 7 * 9 + 8 * 10);
  EXPECT_EQ(lagged[2], 1 * 5 + 2 * 6);
  for (int k = 3; k <= kMaxLag; ++k) EXPECT_EQ(lagged[k], 0.0);

  // Up to t = 1: two samples of ball 0, two of ball 1.
  const std::vector<double> early = LaggedProducts(shot, 1.0, {1, 2, 3, 4, 7, 8, 9, 10});
  EXPECT_EQ(early[1], 1 * 3 + 2 * 4 + 7 * 9 + 8 * 10);
  EXPECT_EQ(early[2], 0.0);
}

// tau = 1 + 2 (rho_1 + rho_2 + ...), summed up to the first autocorrelation that is not
// positive (a later positive one left out); no residuals at all are independent.
TEST(CorrelationTime, SumsTheAutocorrelationsUpToTheFirstThatIsNotPositive) {
  EXPECT_DOUBLE_EQ(CorrelationTime({4.0, 2.0, 1.0, -0.4, 1.2}), 1.0 + 2.0 * (0.5 + 0.25));
  EXPECT_EQ(CorrelationTime({4.0, 0.0, 3.0}), 1.0);
  EXPECT_EQ(CorrelationTime({0.0, 0.0}), 1.0);
}

// Independent noise has a correlation time of 1; AR(1) noise, e_i = rho e_{i-1} + w_i, has
// (1 + rho) / (1 - rho): 9 frames for rho = 0.8, what a filtered track's errors look like. (The
// estimate is biased up a little: it sums the noise of the small correlations too until one
// comes out negative.)
TEST(CorrelationTime, IsOneForIndependentNoiseAndThatOfAnAr1Process) {
  constexpr std::size_t kSamples = 400000;
  std::mt19937_64 random(3);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (double rho : {0.0, 0.5, 0.8}) {
    std::vector<double> r(2 * kSamples);
    double x = 0.0, y = 0.0;
    for (std::size_t i = 0; i < kSamples; ++i) {
      x = rho * x + gauss(random);
      y = rho * y + gauss(random);
      r[2 * i] = x;
      r[2 * i + 1] = y;
    }
    const double tau = CorrelationTime(LaggedProducts(ShotOf({kSamples}), 1e9, r));
    EXPECT_NEAR(tau, (1.0 + rho) / (1.0 - rho), 0.1 * (1.0 + rho) / (1.0 - rho)) << rho;
  }
}

}  // namespace
}  // namespace billiard::shot_fit
