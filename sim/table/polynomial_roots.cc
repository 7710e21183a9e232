#include "sim/table/polynomial_roots.h"

#include <algorithm>
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

// The coefficients of a polynomial of degree N, lowest order first, c[N] != 0.
template <int N>
using Coefficients = std::array<double, N + 1>;

template <int N>
double Value(const Coefficients<N>& c, double t) {
  double value = c[N];
  for (int k = N - 1; k >= 0; --k) value = value * t + c[k];
  return value;
}

template <int N>
void ValueAndSlope(const Coefficients<N>& c, double t, double* value, double* slope) {
  double v = c[N];
  double s = 0.0;
  for (int k = N - 1; k >= 0; --k) {
    s = s * t + v;
    v = v * t + c[k];
  }
  *value = v;
  *slope = s;
}

// sum_k |c_k| x^k for x >= 0: the scale of the rounding of p evaluated where |t| = x.
template <int N>
double Magnitude(const Coefficients<N>& c, double x) {
  double magnitude = std::abs(c[N]);
  for (int k = N - 1; k >= 0; --k) magnitude = magnitude * x + std::abs(c[k]);
  return magnitude;
}

template <int N>
double RoundingOfValue(const Coefficients<N>& c, double t) {
  return kRoundingUlps * kUnitRoundoff * Magnitude<N>(c, std::abs(t));
}

template <int N>
Coefficients<N - 1> Derivative(const Coefficients<N>& c) {
  Coefficients<N - 1> derivative;
  for (int k = 0; k < N; ++k) derivative[k] = (k + 1) * c[k + 1];
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
template <int N>
bool ClearOfZeroOn(const Coefficients<N>& c, double lo, double hi) {
  const double width = hi - lo;
  // Taylor shift to lo by repeated synthetic division, then scaled to s = (t - lo) / width.
  Coefficients<N> shifted = c;
  for (int i = 0; i < N; ++i) {
    for (int j = N - 1; j >= i; --j) shifted[j] += lo * shifted[j + 1];
  }
  double width_power = 1.0;
  for (int k = 1; k <= N; ++k) {
    width_power *= width;
    shifted[k] *= width_power;
  }
  const double margin = 2.0 * RoundingOfValue<N>(c, std::abs(lo) + width);
  const bool positive = shifted[0] > 0.0;
  for (int i = 0; i <= N; ++i) {
    double bernstein = 0.0;
    for (int k = 0; k <= i; ++k) bernstein += kBernsteinWeight[N][i][k] * shifted[k];
    if (std::abs(bernstein) <= margin || (bernstein > 0.0) != positive) return false;
  }
  return true;
}

template <int N>
double Curvature(const Coefficients<N>& c, double t) {
  double curvature = 0.0;
  for (int k = N; k >= 2; --k) curvature = curvature * t + k * (k - 1) * c[k];
  return curvature;
}

// An end of a piece: where it is, p there, and whether it is a critical point of p.
struct PieceEnd {
  double t;
  double value;
  bool critical;
};

// Where Newton starts in (a, b). For a quadratic, the root of the quadratic formula (in its
// cancellation-free form) that falls there, which Newton then only confirms. Otherwise, next to
// a critical end e, the root of the Taylor model p(e) + p''(e) (t - e)^2 / 2 (at the end with
// the smaller |p| when both are critical): there the slope vanishes, and a root near e (a near
// graze) would cost a distant start a long run of linear steps. Failing those, the secant point.
template <int N>
double StartInPiece(const Coefficients<N>& c, const PieceEnd& a, const PieceEnd& b) {
  const auto inside = [&](double t) { return t > a.t && t < b.t; };
  if constexpr (N == 2) {
    const double discriminant = c[1] * c[1] - 4.0 * c[2] * c[0];
    if (discriminant >= 0.0) {
      const double q = -0.5 * (c[1] + std::copysign(std::sqrt(discriminant), c[1]));
      for (const double root : {q / c[2], c[0] / q}) {
        if (inside(root)) return root;
      }
    }
  } else {
    const bool from_a = a.critical && (!b.critical || std::abs(a.value) < std::abs(b.value));
    if (from_a || b.critical) {
      const PieceEnd& end = from_a ? a : b;
      const double offset = std::sqrt(-2.0 * end.value / Curvature<N>(c, end.t));
      const double model_root = from_a ? end.t + offset : end.t - offset;
      if (inside(model_root)) return model_root;
    }
  }
  const double secant = a.t - a.value * (b.t - a.t) / (b.value - a.value);
  return inside(secant) ? secant : a.t + 0.5 * (b.t - a.t);
}

// The one root of p between the ends of a piece, where p is monotone and the values at the ends
// are nonzero of opposite signs: Newton's iteration kept inside the shrinking bracket, bisecting
// whenever Newton would leave it or fails to halve its previous step (rtsafe, Press et al. 2007,
// section 9.4).
template <int N>
double RootInMonotonePiece(const Coefficients<N>& c, const PieceEnd& start, const PieceEnd& end) {
  const bool rising = end.value > 0.0;
  double x = StartInPiece<N>(c, start, end);
  double a = start.t, b = end.t;
  double last_step = b - a;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    double value, slope;
    ValueAndSlope<N>(c, x, &value, &slope);
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
// for a run of them. At most N roots: each root owns a distinct piece.
template <int N>
int RootsOf(const Coefficients<N>& c, double lo, double hi, StartRule start_rule, int max_roots,
            double* roots) {
  if constexpr (N == 0) {
    return 0;  // a nonzero constant
  } else {
    if (ClearOfZeroOn<N>(c, lo, hi)) return 0;
    std::array<double, N + 1> points;
    int num_points = 0;
    points[num_points++] = lo;
    if constexpr (N >= 2) {
      std::array<double, N - 1> critical;
      const int num_critical = RootsOf<N - 1>(Derivative<N>(c), lo, hi, StartRule::kWithinRounding,
                                              N - 1, critical.data());
      for (int i = 0; i < num_critical; ++i) {
        if (critical[i] > points[num_points - 1] && critical[i] < hi) {
          points[num_points++] = critical[i];
        }
      }
    }
    if (hi > lo) points[num_points++] = hi;

    int num_roots = 0;
    PieceEnd previous{};
    bool previous_near_zero = false;
    for (int i = 0; i < num_points && num_roots < max_roots; ++i) {
      const PieceEnd point{points[i], Value<N>(c, points[i]), i > 0 && i < num_points - 1};
      const bool near_zero = (i > 0 || start_rule == StartRule::kWithinRounding) &&
                             std::abs(point.value) <= RoundingOfValue<N>(c, point.t);
      if (near_zero) {
        if (!previous_near_zero) roots[num_roots++] = point.t;
      } else if (i > 0 && !previous_near_zero && (point.value > 0.0) != (previous.value > 0.0)) {
        roots[num_roots++] = RootInMonotonePiece<N>(c, previous, point);
      }
      previous = point;
      previous_near_zero = near_zero;
    }
    return num_roots;
  }
}

template <int N>
int RootsOfLeading(const Quartic& c, double lo, double hi, StartRule start_rule, int max_roots,
                   double* roots) {
  Coefficients<N> leading;
  std::copy(c.begin(), c.begin() + N + 1, leading.begin());
  return RootsOf<N>(leading, lo, hi, start_rule, max_roots, roots);
}

// The true degree of p (its highest nonzero coefficient), after checking the arguments.
int CheckedDegree(const Quartic& c, double lo, double hi, const char* caller) {
  for (const double coefficient : c) {
    if (!std::isfinite(coefficient)) {
      throw std::invalid_argument(std::string(caller) + ": a coefficient is not finite");
    }
  }
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) {
    throw std::invalid_argument(std::string(caller) +
                                ": the interval [lo, hi] needs finite lo <= hi");
  }
  int degree = kMaxDegree;
  while (degree >= 0 && c[degree] == 0.0) --degree;
  if (degree < 0) {
    throw std::invalid_argument(std::string(caller) + ": p is identically zero, every t is a root");
  }
  return degree;
}

int RootsOfDegree(const Quartic& c, int degree, double lo, double hi, StartRule start_rule,
                  int max_roots, double* roots) {
  switch (degree) {
    case 4:
      return RootsOfLeading<4>(c, lo, hi, start_rule, max_roots, roots);
    case 3:
      return RootsOfLeading<3>(c, lo, hi, start_rule, max_roots, roots);
    case 2:
      return RootsOfLeading<2>(c, lo, hi, start_rule, max_roots, roots);
    case 1:
      return RootsOfLeading<1>(c, lo, hi, start_rule, max_roots, roots);
    default:
      return 0;  // a nonzero constant
  }
}

}  // namespace

double Evaluate(const Quartic& p, double t) { return Value<kMaxDegree>(p, t); }

int RootsInInterval(const Quartic& p, double lo, double hi, std::array<double, 4>* roots) {
  const int degree = CheckedDegree(p, lo, hi, "RootsInInterval");
  return RootsOfDegree(p, degree, lo, hi, StartRule::kWithinRounding, kMaxDegree, roots->data());
}

std::optional<double> FirstNonPositive(const Quartic& p, double lo, double hi) {
  const int degree = CheckedDegree(p, lo, hi, "FirstNonPositive");
  if (Evaluate(p, lo) <= 0.0) return lo;
  double root;
  if (RootsOfDegree(p, degree, lo, hi, StartRule::kNotARoot, 1, &root) == 0) return std::nullopt;
  return root;
}

}  // namespace billiard::table
