// The linear algebra of a Rosenbrock step: the stage matrix M = c I - J, c = 1/(gamma h),
// inverted once per step and applied once per stage (six times for RODAS4, rodas4.h).
//
// Why not Eigen's PartialPivLU: at 7x7 its general code and permutation objects cost more than
// the arithmetic (issue 16 measured 181 ns for the 7x7 LU against 118 ns hand-written), and the
// ball's matrix has structure that removes most of it. Its dynamics do not depend on where the
// ball is (X, Y), so the columns of J for X and Y are zero and M is block upper triangular:
//
//     M = [ c I2   -J_pu        ]     J_pu = d(X', Y') / d(vx, vy, wx, wy, wz)
//         [ 0       c I5 - J_uu ]     J_uu = d(v', w') / d(vx, vy, wx, wy, wz)
//
// Only the 5x5 block needs inverting (a fifth of the 7x7's work), and its inverse is formed
// outright, so that each of the six solves is a matrix-vector product: the stages are one chain
// of dependent operations, and a product is a shorter chain than forward and back substitution
// (11 % of a simulation, measured on Figs. 6-10). The position rows of a solution follow by
// substitution, g_p = (r_p + J_pu g_u) / c. A system declares that structure with
//   static constexpr bool kTranslationInvariant = true;
// any other gets the full 7x7 inverse.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <type_traits>
#include <utility>

#include "sim/physics/ball_state.h"

namespace billiard::physics {

// Whether System declares kTranslationInvariant = true (its derivative ignores X and Y).
template <class System, class = void>
struct IsTranslationInvariant : std::false_type {};
template <class System>
struct IsTranslationInvariant<System, std::void_t<decltype(System::kTranslationInvariant)>>
    : std::bool_constant<System::kTranslationInvariant> {};

// The inverse of a fixed-size matrix by Gauss-Jordan elimination with partial pivoting, in place
// (Golub and Van Loan 2013, section 3.2.11; its accuracy is that of the LU-based inverse,
// Higham 2002, section 14.4), the loops unrolled (GCC leaves nested loops rolled by itself, which
// had cost the LU this replaced 44 ns a 5x5 solve, not 8). One sweep of n eliminations, where an
// LU and the inverse from it are three dependent sweeps: 94 ns instead of 105 for the 5x5 block
// along Fig. 10, measured chained, and 4-6 % of a simulation. A singular matrix gives an infinite or NaN inverse, and the
// step controller rejects the step.
template <int N>
Eigen::Matrix<double, N, N> PivotedInverse(Eigen::Matrix<double, N, N> a) {
  std::array<int, N> swapped_with;
#pragma GCC unroll 8
  for (int k = 0; k < N; ++k) {
    int pivot = k;
    double largest = std::abs(a(k, k));
#pragma GCC unroll 8
    for (int i = k + 1; i < N; ++i) {
      const double candidate = std::abs(a(i, k));
      const bool larger = candidate > largest;
      pivot = larger ? i : pivot;
      largest = larger ? candidate : largest;
    }
    swapped_with[k] = pivot;
    if (pivot != k) a.row(k).swap(a.row(pivot));
    // Row k becomes row k of the inverse's work: its pivot column holds 1 / pivot, and every
    // other row is cleared in column k, which then holds that row's part of the inverse.
    const double inverse_pivot = 1.0 / a(k, k);
    a(k, k) = 1.0;
    a.row(k) *= inverse_pivot;
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) {
      if (i == k) continue;
      const double factor = a(i, k);
      a(i, k) = 0.0;
      a.row(i) -= factor * a.row(k);
    }
  }
  // The row exchanges of the matrix are column exchanges of its inverse, undone in reverse.
#pragma GCC unroll 8
  for (int k = N - 1; k >= 0; --k) {
    if (swapped_with[k] != k) a.col(k).swap(a.col(swapped_with[k]));
  }
  return a;
}

// M = c I - J for a system that is translation invariant or not (see the file comment).
template <bool kTranslationInvariant>
class StageMatrix {
 public:
  using Jacobian = Eigen::Matrix<double, 7, 7>;

  void Invert(const Jacobian& jac, double c) {
    if constexpr (kTranslationInvariant) {
      inverse_ = PivotedInverse<5>(c * Block::Identity() - jac.bottomRightCorner<5, 5>());
      position_by_motion_ = jac.topRightCorner<2, 5>();
      inverse_c_ = 1.0 / c;
    } else {
      inverse_ = PivotedInverse<7>(c * Block::Identity() - jac);
    }
  }

  // M^-1 r, inlined into the stages, which wait on it.
  EIGEN_ALWAYS_INLINE BallState Solve(const BallState& r) const {
    if constexpr (kTranslationInvariant) {
      BallState g;
      g.tail<5>() = inverse_ * r.tail<5>();
      g.head<2>() = (r.head<2>() + position_by_motion_ * g.tail<5>()) * inverse_c_;
      return g;
    } else {
      return inverse_ * r;
    }
  }

 private:
  static constexpr int kBlockSize = kTranslationInvariant ? 5 : 7;
  using Block = Eigen::Matrix<double, kBlockSize, kBlockSize>;
  Block inverse_;
  Eigen::Matrix<double, 2, 5> position_by_motion_;  // J_pu
  double inverse_c_ = 0.0;
};

}  // namespace billiard::physics
