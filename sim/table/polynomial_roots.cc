#include "sim/table/polynomial_roots.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace billiard::table {
namespace {

constexpr int kMaxDegree = 4;
constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2.0;
// "Within rounding of 0", in units of u times sum_k |c_k| |t|^k (the header says why 16).
constexpr double kRoundingUlps = 16.0;
// Newton has converged when its step is a few ulps of the root: the step after that would be
// below the rounding of the root itself.
constexpr double kRelativeStepTolerance = 4.0 * kUnitRoundoff;
// A guard only: the bracketed iteration halves the bracket at least every other step, so it
// reaches a few ulps from any bracket of doubles of comparable magnitude well within this.
constexpr int kMaxIterations = 200;

// p with its true degree: c[degree] != 0 (degree 0 is a nonzero constant).
struct Polynomial {
  std::array<double, kMaxDegree + 1> c{};
  int degree = 0;
};

double Value(const Polynomial& p, double t) {
  double value = p.c[p.degree];
  for (int k = p.degree - 1; k >= 0; --k) value = value * t + p.c[k];
  return value;
}

void ValueAndSlope(const Polynomial& p, double t, double* value, double* slope) {
  double v = p.c[p.degree];
  double s = 0.0;
  for (int k = p.degree - 1; k >= 0; --k) {
    s = s * t + v;
    v = v * t + p.c[k];
  }
  *value = v;
  *slope = s;
}

// sum_k |c_k| x^k for x >= 0: the scale of the rounding of p evaluated where |t| = x.
double Magnitude(const Polynomial& p, double x) {
  double magnitude = std::abs(p.c[p.degree]);
  for (int k = p.degree - 1; k >= 0; --k) magnitude = magnitude * x + std::abs(p.c[k]);
  return magnitude;
}

double RoundingOfValue(const Polynomial& p, double t) {
  return kRoundingUlps * kUnitRoundoff * Magnitude(p, std::abs(t));
}

Polynomial Derivative(const Polynomial& p) {
  Polynomial derivative;
  derivative.degree = p.degree - 1;
  for (int k = 0; k < p.degree; ++k) derivative.c[k] = (k + 1) * p.c[k + 1];
  return derivative;
}

// kBernsteinWeight[n][i][k] = C(i, k) / C(n, k): the Bernstein coefficients of degree n on
// [0, 1] are b_i = sum_{k <= i} C(i, k) / C(n, k) d_k for p(s) = sum_k d_k s^k (Farouki and
// Rajan 1988, "Algorithms for polynomials in Bernstein form", Comput. Aided Geom. Des. 5(1)).
using BernsteinWeights =
    std::array<std::array<std::array<double, kMaxDegree + 1>, kMaxDegree + 1>, kMaxDegree + 1>;

constexpr double Binomial(int n, int k) {
  double binomial = 1.0;
  for (int j = 1; j <= k; ++j) binomial = binomial * (n - k + j) / j;
  return binomial;
}

constexpr BernsteinWeights MakeBernsteinWeights() {
  BernsteinWeights weights{};
  for (int n = 0; n <= kMaxDegree; ++n) {
    for (int i = 0; i <= n; ++i) {
      for (int k = 0; k <= i; ++k) weights[n][i][k] = Binomial(i, k) / Binomial(n, k);
    }
  }
  return weights;
}

constexpr BernsteinWeights kBernsteinWeight = MakeBernsteinWeights();

// True when p keeps one sign, clear of rounding, on all of [lo, hi]: every Bernstein
// coefficient of p on [lo, hi] has that sign and exceeds the margin, and p is a convex
// combination of them there. The margin is twice the rounding of a value: the coefficients'
// own rounding (3n u sum_j |c_j| (|lo| + h)^j through the shift and the sums) plus the rounding
// that decides a touch. The quick exit of every pair that does not come near contact.
bool ClearOfZeroOn(const Polynomial& p, double lo, double hi) {
  const int n = p.degree;
  const double width = hi - lo;
  // Taylor shift to lo by repeated synthetic division, then scaled to s = (t - lo) / width.
  std::array<double, kMaxDegree + 1> shifted = p.c;
  for (int i = 0; i < n; ++i) {
    for (int j = n - 1; j >= i; --j) shifted[j] += lo * shifted[j + 1];
  }
  double width_power = 1.0;
  for (int k = 1; k <= n; ++k) {
    width_power *= width;
    shifted[k] *= width_power;
  }
  const double margin = 2.0 * RoundingOfValue(p, std::abs(lo) + width);
  const bool positive = shifted[0] > 0.0;
  for (int i = 0; i <= n; ++i) {
    double bernstein = 0.0;
    for (int k = 0; k <= i; ++k) bernstein += kBernsteinWeight[n][i][k] * shifted[k];
    if (std::abs(bernstein) <= margin || (bernstein > 0.0) != positive) return false;
  }
  return true;
}

// The one root of p in (a, b), where p is monotone and value_a, value_b are nonzero of opposite
// signs: Newton's iteration kept inside the shrinking bracket, bisecting whenever Newton would
// leave it or fails to halve its previous step (rtsafe, Press et al. 2007, section 9.4).
double RootInMonotonePiece(const Polynomial& p, double a, double value_a, double b,
                           double value_b) {
  const bool rising = value_b > 0.0;
  // Start at the secant point: inside the bracket, and unlike an end that is a critical
  // point, never where the slope vanishes.
  double x = a - value_a * (b - a) / (value_b - value_a);
  if (!(x > a && x < b)) x = a + 0.5 * (b - a);
  double last_step = b - a;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    double value, slope;
    ValueAndSlope(p, x, &value, &slope);
    if (value == 0.0) return x;
    if ((value > 0.0) == rising) {
      b = x;
    } else {
      a = x;
    }
    double next = x - value / slope;
    if (!(next > a && next < b) || 2.0 * std::abs(next - x) > std::abs(last_step)) {
      next = a + 0.5 * (b - a);
    }
    last_step = next - x;
    const bool bracket_exhausted = next <= a || next >= b;
    if (bracket_exhausted || std::abs(last_step) <= kRelativeStepTolerance * std::abs(next)) {
      return next;
    }
    x = next;
  }
  return x;
}

// Whether the start lo may be a root by being within rounding of 0 (RootsInInterval), or only
// by p(lo) <= 0, which FirstNonPositive has settled before it searches.
enum class StartRule { kWithinRounding, kNotARoot };

// The roots of p in [lo, hi], ascending, at most max_roots of them (the search stops there):
// the pieces between consecutive critical points, each with a root when its ends have opposite
// signs clear of rounding; a critical point or end within rounding of 0 is a root itself, once
// for a run of them. At most p.degree roots: each root owns a distinct piece.
int RootsOf(const Polynomial& p, double lo, double hi, StartRule start_rule, int max_roots,
            double* roots) {
  if (p.degree == 0 || ClearOfZeroOn(p, lo, hi)) return 0;
  std::array<double, kMaxDegree + 1> points;
  int num_points = 0;
  points[num_points++] = lo;
  if (p.degree >= 2) {
    std::array<double, kMaxDegree - 1> critical;
    const int num_critical =
        RootsOf(Derivative(p), lo, hi, StartRule::kWithinRounding, p.degree - 1, critical.data());
    for (int i = 0; i < num_critical; ++i) {
      if (critical[i] > points[num_points - 1] && critical[i] < hi) {
        points[num_points++] = critical[i];
      }
    }
  }
  if (hi > lo) points[num_points++] = hi;

  int num_roots = 0;
  double previous_value = 0.0;
  bool previous_near_zero = false;
  for (int i = 0; i < num_points && num_roots < max_roots; ++i) {
    const double value = Value(p, points[i]);
    const bool near_zero = (i > 0 || start_rule == StartRule::kWithinRounding) &&
                           std::abs(value) <= RoundingOfValue(p, points[i]);
    if (near_zero) {
      if (!previous_near_zero) roots[num_roots++] = points[i];
    } else if (i > 0 && !previous_near_zero && (value > 0.0) != (previous_value > 0.0)) {
      roots[num_roots++] = RootInMonotonePiece(p, points[i - 1], previous_value, points[i], value);
    }
    previous_value = value;
    previous_near_zero = near_zero;
  }
  return num_roots;
}

// p with its true degree, after checking the arguments.
Polynomial Checked(const Quartic& c, double lo, double hi, const char* caller) {
  for (const double coefficient : c) {
    if (!std::isfinite(coefficient)) {
      throw std::invalid_argument(std::string(caller) + ": a coefficient is not finite");
    }
  }
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) {
    throw std::invalid_argument(std::string(caller) +
                                ": the interval [lo, hi] needs finite lo <= hi");
  }
  Polynomial p;
  p.c = c;
  p.degree = kMaxDegree;
  while (p.degree >= 0 && c[p.degree] == 0.0) --p.degree;
  if (p.degree < 0) {
    throw std::invalid_argument(std::string(caller) + ": p is identically zero, every t is a root");
  }
  return p;
}

}  // namespace

double Evaluate(const Quartic& p, double t) { return Value(Polynomial{p, kMaxDegree}, t); }

int RootsInInterval(const Quartic& p, double lo, double hi, std::array<double, 4>* roots) {
  const Polynomial polynomial = Checked(p, lo, hi, "RootsInInterval");
  return RootsOf(polynomial, lo, hi, StartRule::kWithinRounding, kMaxDegree, roots->data());
}

std::optional<double> FirstNonPositive(const Quartic& p, double lo, double hi) {
  const Polynomial polynomial = Checked(p, lo, hi, "FirstNonPositive");
  if (Value(polynomial, lo) <= 0.0) return lo;
  double root;
  if (RootsOf(polynomial, lo, hi, StartRule::kNotARoot, 1, &root) == 0) return std::nullopt;
  return root;
}

}  // namespace billiard::table
