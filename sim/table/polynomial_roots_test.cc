// The root finder against polynomials built from known roots, against the companion-matrix
// eigenvalues of Eigen's PolynomialSolver on random quartics, and on ball-ball contacts built to
// happen at a known time.
#include "sim/table/polynomial_roots.h"

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/Polynomials>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace billiard::table {
namespace {

constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2.0;
// A pool ball: 57.15 mm in diameter (WPA equipment specifications).
constexpr double kBallRadius = 0.028575;

// leading * prod_i (t - r_i), coefficients lowest order first.
Quartic FromRoots(double leading, std::initializer_list<double> roots) {
  Quartic p{};
  p[0] = leading;
  int degree = 0;
  for (const double r : roots) {
    for (int k = degree + 1; k >= 1; --k) p[k] = p[k - 1] - r * p[k];
    p[0] *= -r;
    ++degree;
  }
  return p;
}

// sum_k |c_k| |t|^k: the scale of the rounding of p at t.
double Magnitude(const Quartic& p, double t) {
  double magnitude = 0.0;
  for (int k = 4; k >= 0; --k) magnitude = magnitude * std::abs(t) + std::abs(p[k]);
  return magnitude;
}

double Slope(const Quartic& p, double t) {
  return p[1] + t * (2.0 * p[2] + t * (3.0 * p[3] + t * 4.0 * p[4]));
}

// How far rounding can move a simple root r: a perturbation dp of p moves it by dp / |p'(r)|,
// and the coefficients and their evaluation carry a few tens of u times sum_k |c_k| |r|^k.
double SimpleRootTolerance(const Quartic& p, double r) {
  return 64.0 * kUnitRoundoff * Magnitude(p, r) / std::abs(Slope(p, r));
}

std::vector<double> Roots(const Quartic& p, double lo, double hi) {
  std::array<double, 4> roots;
  const int count = RootsInInterval(p, lo, hi, &roots);
  return {roots.begin(), roots.begin() + count};
}

void ExpectSimpleRoots(const Quartic& p, double lo, double hi, const std::vector<double>& truth) {
  const std::vector<double> found = Roots(p, lo, hi);
  ASSERT_EQ(found.size(), truth.size());
  for (size_t i = 0; i < truth.size(); ++i) {
    EXPECT_NEAR(found[i], truth[i], SimpleRootTolerance(p, truth[i])) << "root " << i;
  }
}

TEST(PolynomialRoots, EvaluateIsTheSumOfTheTerms) {
  EXPECT_EQ(Evaluate({1.0, 2.0, 3.0, 4.0, 5.0}, 2.0), 1.0 + 4.0 + 12.0 + 32.0 + 80.0);
  EXPECT_EQ(Evaluate({-7.0, 0.0, 0.0, 0.0, 0.0}, 3.5), -7.0);
}

TEST(PolynomialRoots, FourSimpleRootsAreFoundAscendingToRounding) {
  const Quartic p = FromRoots(1.0, {3.0, -1.5, 0.7, 0.25});
  ExpectSimpleRoots(p, -2.0, 4.0, {-1.5, 0.25, 0.7, 3.0});
  ExpectSimpleRoots(FromRoots(-2.5, {3.0, -1.5, 0.7, 0.25}), -2.0, 4.0, {-1.5, 0.25, 0.7, 3.0});
}

TEST(PolynomialRoots, OnlyTheRootsInsideTheIntervalAreReturned) {
  const Quartic p = FromRoots(1.0, {3.0, -1.5, 0.7, 0.25});
  ExpectSimpleRoots(p, 0.0, 1.0, {0.25, 0.7});
  ExpectSimpleRoots(p, 0.3, 0.6, {});
  ExpectSimpleRoots(p, 3.5, 100.0, {});
}

TEST(PolynomialRoots, RootsAtTheEndsOfTheIntervalAreFound) {
  const Quartic p = FromRoots(1.0, {0.0, 1.0, 2.0, -3.0});
  ExpectSimpleRoots(p, 0.0, 2.0, {0.0, 1.0, 2.0});
  // 0.1 and 0.7 are not doubles: p at the ends is a rounding error away from 0.
  const Quartic q = FromRoots(1.0, {0.1, 0.7, 5.0, -3.0});
  ExpectSimpleRoots(q, 0.1, 0.7, {0.1, 0.7});
  ExpectSimpleRoots(q, 0.7, 0.7, {0.7});
  EXPECT_EQ(FirstNonPositive(FromRoots(-1.0, {2.0, -5.0}), 0.0, 2.0), 2.0);
}

TEST(PolynomialRoots, ADoubleRootIsFoundOnceAtItsCriticalPoint) {
  // (t - 0.3)^2 (t^2 + 1): p touches zero at 0.3 without crossing. The double root is a simple
  // root of p', as well conditioned as any simple root.
  Quartic p = FromRoots(1.0, {0.3, 0.3});
  p = {p[0], p[1], p[2] + p[0], p[1], p[2]};
  const std::vector<double> found = Roots(p, -1.0, 1.0);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0], 0.3, 1e-14);
  EXPECT_NEAR(FirstNonPositive(p, -1.0, 1.0).value(), 0.3, 1e-14);
}

TEST(PolynomialRoots, ATouchCountsWithinRoundingAndANearMissDoesNot) {
  // (t - 0.3)^2 (4 - t^2) >= 0 on [-1, 1], zero at 0.3 only.
  const Quartic touching = FromRoots(-1.0, {0.3, 0.3, -2.0, 2.0});
  auto raised = [&](double offset) {
    Quartic p = touching;
    p[0] += offset;
    return p;
  };
  // Raised by one rounding unit of p at 0.3: still a touch.
  const Quartic grazing = raised(kUnitRoundoff * Magnitude(touching, 0.3));
  ASSERT_EQ(Roots(grazing, -1.0, 1.0).size(), 1u);
  EXPECT_NEAR(Roots(grazing, -1.0, 1.0)[0], 0.3, 1e-14);
  EXPECT_NEAR(FirstNonPositive(grazing, -1.0, 1.0).value(), 0.3, 1e-14);
  // The same touch at an end of the interval, and at the end of a FirstNonPositive search.
  EXPECT_EQ(Roots(grazing, 0.3, 1.0), std::vector<double>{0.3});
  EXPECT_EQ(Roots(grazing, -1.0, 0.3), std::vector<double>{0.3});
  EXPECT_EQ(FirstNonPositive(grazing, -1.0, 0.3), 0.3);
  // Raised by 1e-9, far beyond rounding: a near miss, not a contact.
  EXPECT_TRUE(Roots(raised(1e-9), -1.0, 1.0).empty());
  EXPECT_FALSE(FirstNonPositive(raised(1e-9), -1.0, 1.0).has_value());
  // Lowered by 1e-9: near 0.3, p = 3.91 (t - 0.3)^2 - 1e-9, crossing at 0.3 -+ sqrt(1e-9 / 3.91).
  const Quartic overlap = raised(-1e-9);
  const double half_gap = std::sqrt(1e-9 / (4.0 - 0.09));
  const std::vector<double> crossings = Roots(overlap, -1.0, 1.0);
  ASSERT_EQ(crossings.size(), 2u);
  EXPECT_NEAR(crossings[0], 0.3 - half_gap, 1e-9);
  EXPECT_NEAR(crossings[1], 0.3 + half_gap, 1e-9);
  EXPECT_EQ(FirstNonPositive(overlap, -1.0, 1.0).value(), crossings[0]);
}

TEST(PolynomialRoots, RootsTooCloseToResolveAreReportedInsideTheirCluster) {
  // Roots 1e-9 apart: between them |p| <= 2.25 (5e-10)^2 = 6e-19, far below the rounding of p
  // (~1e-15), so no method in doubles can separate them; the cluster counts once, inside the
  // band where p is within rounding of 0 (half-width sqrt(16 u sum |c_k| / 2.25) = 4e-8).
  const Quartic p = FromRoots(1.0, {0.5, 0.5 + 1e-9, -1.0, 2.0});
  const double band = std::sqrt(16.0 * kUnitRoundoff * Magnitude(p, 0.5) / 2.25);
  const std::vector<double> found = Roots(p, -2.0, 3.0);
  ASSERT_EQ(found.size(), 3u);
  EXPECT_NEAR(found[0], -1.0, SimpleRootTolerance(p, -1.0));
  EXPECT_NEAR(found[1], 0.5, band);
  EXPECT_NEAR(found[2], 2.0, SimpleRootTolerance(p, 2.0));
  // -p > 0 on (-1, 2) but at the cluster.
  const Quartic minus_p = {-p[0], -p[1], -p[2], -p[3], -p[4]};
  EXPECT_NEAR(FirstNonPositive(minus_p, 0.0, 3.0).value(), 0.5, band);
  // 1e-6 apart the dip (6e-13) is far above rounding: two roots, each as well placed as its
  // slope (2.25e-6) allows.
  const Quartic resolvable = FromRoots(1.0, {0.5, 0.5 + 1e-6, -1.0, 2.0});
  ExpectSimpleRoots(resolvable, 0.0, 1.0, {0.5, 0.5 + 1e-6});
}

TEST(PolynomialRoots, AVanishingOrTinyLeadingCoefficientDropsTheDegree) {
  // (t - 1)(t - 2) as a quartic with c4 = c3 = 0, then with c4 = 1e-300, which moves the roots
  // by ~1e-300: below the rounding of either.
  ExpectSimpleRoots({2.0, -3.0, 1.0, 0.0, 0.0}, 0.0, 10.0, {1.0, 2.0});
  ExpectSimpleRoots({2.0, -3.0, 1.0, 0.0, 1e-300}, 0.0, 10.0, {1.0, 2.0});
  ExpectSimpleRoots({2.0, -3.0, 1.0, -1e-300, 1e-300}, 0.0, 10.0, {1.0, 2.0});
  ExpectSimpleRoots({-1.0, 2.0, 0.0, 0.0, 0.0}, 0.0, 1.0, {0.5});
  ExpectSimpleRoots({-1.0, 0.0, 0.0, 0.0, 0.0}, -5.0, 5.0, {});
  EXPECT_EQ(FirstNonPositive({2.0, -3.0, 1.0, 0.0, 0.0}, 0.0, 10.0), 1.0);
}

TEST(PolynomialRoots, RootsSpanningElevenDecadesAreEachFoundToRounding) {
  const Quartic p = FromRoots(1.0, {1e-6, 1e-2, 1e2, 1e5});
  ExpectSimpleRoots(p, 0.0, 2e5, {1e-6, 1e-2, 1e2, 1e5});
  for (const double r : {1e-6, 1e-2, 1e2, 1e5}) {
    EXPECT_LT(SimpleRootTolerance(p, r), 1e-12 * r);  // so the roots are relative 1e-12 exact
  }
  // Scaling p by 2^-900 or 2^+600 leaves its roots where they were.
  for (const double scale : {std::ldexp(1.0, -900), std::ldexp(1.0, 600)}) {
    const Quartic scaled = {scale * p[0], scale * p[1], scale * p[2], scale * p[3], scale * p[4]};
    const std::vector<double> found = Roots(scaled, 0.0, 2e5);
    EXPECT_EQ(found, Roots(p, 0.0, 2e5));
  }
}

TEST(PolynomialRoots, FirstNonPositiveStartsAfterAContactThatIsSeparating) {
  // -(t - 0.5)(t - 2), from one ulp after its root 0.5: p(lo) is a rounding error above 0 and
  // rising, as for a pair just separated; the next contact is at 2.
  const Quartic p = {-1.0, 2.5, -1.0, 0.0, 0.0};
  const double lo = std::nextafter(0.5, 1.0);
  ASSERT_GT(Evaluate(p, lo), 0.0);
  EXPECT_EQ(FirstNonPositive(p, lo, 3.0), 2.0);
  ExpectSimpleRoots(p, lo, 3.0, {lo, 2.0});  // as a root of p, lo does count
  EXPECT_EQ(FirstNonPositive(FromRoots(-1.0, {1.0, 3.0}), 0.0, 2.0), 0.0);  // p(0) < 0: lo
}

TEST(PolynomialRoots, BadInputIsRejectedWithAReason) {
  std::array<double, 4> roots;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(RootsInInterval({nan, 1.0, 0.0, 0.0, 0.0}, 0.0, 1.0, &roots), std::invalid_argument);
  EXPECT_THROW(RootsInInterval({1.0, 1.0, 0.0, 0.0, inf}, 0.0, 1.0, &roots), std::invalid_argument);
  EXPECT_THROW(RootsInInterval({1.0, 1.0, 0.0, 0.0, 0.0}, 1.0, 0.0, &roots), std::invalid_argument);
  EXPECT_THROW(RootsInInterval({1.0, 1.0, 0.0, 0.0, 0.0}, 0.0, inf, &roots), std::invalid_argument);
  EXPECT_THROW(FirstNonPositive({0.0, 0.0, 0.0, 0.0, 0.0}, 0.0, 1.0), std::invalid_argument);
}

// Eigen's companion-matrix eigenvalues of p (Eigen's real Schur form gives a real eigenvalue an
// imaginary part of exactly 0).
std::vector<std::complex<double>> ReferenceRoots(const Quartic& p) {
  Eigen::PolynomialSolver<double, 4> solver;
  solver.compute(Eigen::Matrix<double, 5, 1>(p[0], p[1], p[2], p[3], p[4]));
  const auto& roots = solver.roots();
  return {roots.data(), roots.data() + roots.size()};
}

// Random quartics: half with log-uniform coefficients of random sign (mostly two or no real
// roots, of all conditionings), half built from four random real roots (up to four in the
// interval, close ones included).
Quartic RandomQuartic(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0), decades(-3.0, 3.0);
  if (rng() % 2 == 0) {
    Quartic p;
    for (double& c : p) c = std::copysign(std::pow(10.0, decades(rng)), unit(rng));
    return p;
  }
  return FromRoots(std::pow(10.0, decades(rng)),
                   {2.0 * unit(rng), 2.0 * unit(rng), 2.0 * unit(rng), 2.0 * unit(rng)});
}

TEST(PolynomialRoots, NoRootOfTheCompanionMatrixIsMissedInOneHundredThousandQuartics) {
  // A root the reference finds real in [lo, hi] must be among ours within kTolerance, and each
  // of ours must be a reference root (real, or a complex pair of imaginary part below
  // kTolerance: the split of a double root) with |p| within rounding of 0. kTolerance covers
  // the reference's own error at a double root, ~sqrt(u).
  constexpr double kTolerance = 1e-6;
  std::mt19937_64 rng(20220701);
  std::uniform_real_distribution<double> bound(-2.5, 2.5);
  int reference_real_roots_checked = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    const Quartic p = RandomQuartic(rng);
    double lo = bound(rng), hi = bound(rng);
    if (lo > hi) std::swap(lo, hi);
    const std::vector<double> found = Roots(p, lo, hi);
    const std::vector<std::complex<double>> reference = ReferenceRoots(p);
    ASSERT_TRUE(std::is_sorted(found.begin(), found.end()));
    for (const std::complex<double>& z : reference) {
      if (z.imag() != 0.0 || z.real() < lo || z.real() > hi) continue;
      ++reference_real_roots_checked;
      const bool matched = std::any_of(found.begin(), found.end(), [&](double r) {
        return std::abs(r - z.real()) <= kTolerance * std::max(1.0, std::abs(r));
      });
      ASSERT_TRUE(matched) << "trial " << trial << ": missed the root " << z.real();
    }
    for (const double r : found) {
      ASSERT_GE(r, lo);
      ASSERT_LE(r, hi);
      EXPECT_LE(std::abs(Evaluate(p, r)), 32.0 * kUnitRoundoff * Magnitude(p, r))
          << "trial " << trial << " at " << r;
      const bool genuine = std::any_of(reference.begin(), reference.end(), [&](auto z) {
        return std::abs(z.imag()) <= kTolerance && std::abs(z.real() - r) <= kTolerance;
      });
      ASSERT_TRUE(genuine) << "trial " << trial << ": spurious root " << r;
    }
    // FirstNonPositive is the first of them, whenever the start is not itself a root.
    if (Evaluate(p, lo) > 16.0 * kUnitRoundoff * Magnitude(p, lo)) {
      const std::optional<double> first = FirstNonPositive(p, lo, hi);
      ASSERT_EQ(first.has_value(), !found.empty()) << "trial " << trial;
      if (first) {
        ASSERT_EQ(*first, found.front()) << "trial " << trial;
      }
    }
  }
  EXPECT_GT(reference_real_roots_checked, 100000);  // the check was not vacuous
}

TEST(PolynomialRoots, NoRootOfARandomClosePairIsMissed) {
  // Quartics with a pair of roots 1e-3 to 1e-12 apart and two more at least 0.1 from the pair,
  // against the roots they were built from (the companion matrix is itself off by ~sqrt(u) at
  // such a pair). A root r moves under a perturbation dp of p by about dp / |p'(r)|, or by
  // sqrt(2 dp / |p''(r)|) where p'(r) is too small for that: each true root in [lo, hi] must be
  // within twice the smaller of the two of a root found, whether the pair is resolved or not.
  std::mt19937_64 rng(1010);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), decades(-3.0, 3.0),
      gap_decades(-12.0, -3.0), bound(-2.5, 2.5);
  int checked = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    const double r = 2.0 * unit(rng);
    const double gap = std::pow(10.0, gap_decades(rng));
    const double a = 2.0 * unit(rng), b = 2.0 * unit(rng);
    if (std::abs(a - r) < 0.1 || std::abs(b - r) < 0.1) continue;
    const std::array<double, 4> truth = {r, r + gap, a, b};
    const Quartic p = FromRoots(std::pow(10.0, decades(rng)), {r, r + gap, a, b});
    double lo = bound(rng), hi = bound(rng);
    if (lo > hi) std::swap(lo, hi);
    const std::vector<double> found = Roots(p, lo, hi);
    for (const double root : truth) {
      if (root < lo || root > hi) continue;
      ++checked;
      const double perturbation = 32.0 * kUnitRoundoff * Magnitude(p, root);
      const double curvature = 2.0 * p[2] + root * (6.0 * p[3] + root * 12.0 * p[4]);
      const double tolerance = 2.0 * std::min(perturbation / std::abs(Slope(p, root)),
                                              std::sqrt(2.0 * perturbation / std::abs(curvature)));
      const bool matched = std::any_of(found.begin(), found.end(),
                                       [&](double x) { return std::abs(x - root) <= tolerance; });
      ASSERT_TRUE(matched) << "trial " << trial << ": missed the root " << root;
    }
  }
  EXPECT_GT(checked, 100000);
}

// Two balls on parabolic paths x_i(t) = x_i + v_i t + a_i t^2 / 2: their separation
// d(t) = d0 + w t + b t^2 / 2 gives |d(t)|^2 - (2R)^2 as a quartic in t.
Quartic ContactQuartic(const Eigen::Vector2d& d0, const Eigen::Vector2d& w,
                       const Eigen::Vector2d& b) {
  return {d0.squaredNorm() - 4.0 * kBallRadius * kBallRadius, 2.0 * d0.dot(w),
          w.squaredNorm() + d0.dot(b), w.dot(b), 0.25 * b.squaredNorm()};
}

// Separation, relative velocity and relative acceleration arriving at contact d(t*) = 2R n with
// relative velocity w* at t*: run backwards from the contact, d0 = 2R n - w* t* + b t*^2 / 2.
struct Approach {
  Eigen::Vector2d d0, w, b;
};
Approach BackFromContact(double t_contact, const Eigen::Vector2d& normal,
                         const Eigen::Vector2d& w_contact, const Eigen::Vector2d& b) {
  const Eigen::Vector2d w = w_contact - b * t_contact;
  const Eigen::Vector2d d0 =
      2.0 * kBallRadius * normal - w_contact * t_contact + 0.5 * b * t_contact * t_contact;
  return {d0, w, b};
}

TEST(PolynomialRoots, TheFirstRootOfTheContactQuarticIsTheContactTime) {
  // With s = t* - t, |d|^2 - 4R^2 = -4R (w*.n) s + (|w*|^2 + 2R b.n) s^2 - (w*.b) s^3
  // + |b|^2 s^4 / 4. For w*.n < 0 (closing), b.n >= 0 and w*.b <= 0 every term is positive for
  // s > 0: the balls are apart before t*, so t* is the first root. Starts on the table: |d0|
  // below its diagonal, 2.84 m.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), time(0.02, 2.0), speed(0.01, 4.0),
      accel(0.0, 5.0);
  int checked = 0, within_1e12 = 0;
  while (checked < 2000) {
    const double t_contact = time(rng);
    const double theta = angle(rng);
    const Eigen::Vector2d normal(std::cos(theta), std::sin(theta));
    const Eigen::Vector2d tangent(-normal.y(), normal.x());
    const Eigen::Vector2d w_contact = -speed(rng) * normal + (speed(rng) - 2.0) * tangent;
    const double phi = angle(rng);
    const Eigen::Vector2d b = accel(rng) * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    if (b.dot(normal) < 0.0 || w_contact.dot(b) > 0.0) continue;
    const Approach approach = BackFromContact(t_contact, normal, w_contact, b);
    if (approach.d0.norm() > 2.84) continue;
    const Quartic p = ContactQuartic(approach.d0, approach.w, approach.b);
    const std::optional<double> first = FirstNonPositive(p, 0.0, t_contact + 1.0);
    ASSERT_TRUE(first.has_value());
    // 1e-12 relative, unless the rounding of the coefficients alone (a slow approach: p' small)
    // moves the contact further.
    const double tolerance = std::max(1e-12 * t_contact, SimpleRootTolerance(p, t_contact));
    ASSERT_NEAR(*first, t_contact, tolerance) << "contact " << checked;
    if (std::abs(*first - t_contact) <= 1e-12 * t_contact) ++within_1e12;
    ++checked;
  }
  EXPECT_GE(within_1e12, 1990);
}

TEST(PolynomialRoots, BallsWithEqualAccelerationsMeetAtTheRootOfAQuadratic) {
  // b = 0: straight relative motion, |d0 + w t| = 2R at t* = (-d0.w - sqrt((d0.w)^2 - |w|^2
  // (|d0|^2 - 4R^2))) / |w|^2; the quartic's c3 and c4 are exactly 0.
  const Eigen::Vector2d d0(0.9, 0.02), w(-1.3, 0.01);
  const Quartic p = ContactQuartic(d0, w, Eigen::Vector2d::Zero());
  ASSERT_EQ(p[3], 0.0);
  ASSERT_EQ(p[4], 0.0);
  const double dw = d0.dot(w);
  const double t_contact =
      (-dw - std::sqrt(dw * dw -
                       w.squaredNorm() * (d0.squaredNorm() - 4.0 * kBallRadius * kBallRadius))) /
      w.squaredNorm();
  EXPECT_NEAR(FirstNonPositive(p, 0.0, 5.0).value(), t_contact, 1e-12 * t_contact);
}

TEST(PolynomialRoots, AGrazingContactIsFoundAtItsTangentTime) {
  // w*.n = 0 and b parallel to n, b.n >= 0: |d|^2 - 4R^2 = (|w*|^2 + 2R b.n) s^2 + |b|^2 s^4 / 4,
  // zero at t* only: the balls touch without overlapping.
  const double t_contact = 0.8137;
  const Eigen::Vector2d normal = Eigen::Vector2d(3.0, -4.0) / 5.0;
  const Eigen::Vector2d tangent(-normal.y(), normal.x());
  for (const double b_normal : {0.0, 0.4, 3.0}) {
    const Approach approach = BackFromContact(t_contact, normal, 1.7 * tangent, b_normal * normal);
    const Quartic p = ContactQuartic(approach.d0, approach.w, approach.b);
    const std::optional<double> first = FirstNonPositive(p, 0.0, 2.0);
    ASSERT_TRUE(first.has_value()) << "b.n = " << b_normal;
    EXPECT_NEAR(*first, t_contact, 1e-12 * t_contact) << "b.n = " << b_normal;
    // Passing 1 um wider is a miss; 1 um narrower, an overlap entered before t*.
    for (const double offset : {1e-6, -1e-6}) {
      const Approach shifted{approach.d0 + offset * normal, approach.w, approach.b};
      const std::optional<double> shifted_first =
          FirstNonPositive(ContactQuartic(shifted.d0, shifted.w, shifted.b), 0.0, 2.0);
      EXPECT_EQ(shifted_first.has_value(), offset < 0.0) << "offset " << offset;
      if (shifted_first) {
        EXPECT_LT(*shifted_first, t_contact);
      }
    }
  }
}

}  // namespace
}  // namespace billiard::table
