// The linear algebra of a Rosenbrock step: the stage matrix M = c I - J, c = 1/(gamma h),
// factored once per step and solved once per stage (six times for RODAS4, rodas4.h).
//
// Why not Eigen's PartialPivLU: at 7x7 its general code and permutation objects cost more than
// the arithmetic (issue 16 measured 181 ns for the 7x7 LU against 118 ns hand-written), and the
// ball's matrix has structure that removes most of it. Its dynamics do not depend on where the
// ball is (X, Y), so the columns of J for X and Y are zero and M is block upper triangular:
//
//     M = [ c I2   -J_pu        ]     J_pu = d(X', Y') / d(vx, vy, wx, wy, wz)
//         [ 0       c I5 - J_uu ]     J_uu = d(v', w') / d(vx, vy, wx, wy, wz)
//
// Only the 5x5 block needs an LU (a fifth of the 7x7's work), and it is turned into the block's
// inverse, so that each of the six solves is a matrix-vector product: the stages are one chain of
// dependent operations, and a product is a shorter chain than forward and back substitution (11 %
// of a simulation, measured on Figs. 6-10). The position rows of a solution follow by
// substitution, g_p = (r_p + J_pu g_u) / c. A system declares that structure with
//   static constexpr bool kTranslationInvariant = true;
// any other gets the full 7x7 factorization.
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

// LU with partial pivoting of a fixed-size matrix (Golub and Van Loan 2013, algorithm 3.4.1) and
// the inverse from it, the loops unrolled (GCC leaves the nested ones rolled by itself: a 5x5
// solve then took 44 ns, not 8). A singular matrix gives an infinite or NaN inverse, and the step
// controller rejects the step.
template <int N>
class FixedSizeLu {
 public:
  using Matrix = Eigen::Matrix<double, N, N>;

  void Factor(const Matrix& a) {
    lu_ = a;
#pragma GCC unroll 8
    for (int k = 0; k < N; ++k) row_of_[k] = k;
#pragma GCC unroll 8
    for (int k = 0; k < N; ++k) {
      int pivot = k;
#pragma GCC unroll 8
      for (int i = k + 1; i < N; ++i) {
        if (std::abs(lu_(i, k)) > std::abs(lu_(pivot, k))) pivot = i;
      }
      if (pivot != k) {
        lu_.row(k).swap(lu_.row(pivot));
        std::swap(row_of_[k], row_of_[pivot]);
      }
      inverse_diagonal_[k] = 1.0 / lu_(k, k);
#pragma GCC unroll 8
      for (int i = k + 1; i < N; ++i) {
        const double l = lu_(i, k) * inverse_diagonal_[k];
        lu_(i, k) = l;
#pragma GCC unroll 8
        for (int j = k + 1; j < N; ++j) lu_(i, j) -= l * lu_(k, j);
      }
    }
  }

  // A^-1, the solves of all unit vectors at once: each substitution step is a row operation.
  Matrix Inverse() const {
    Matrix y = Matrix::Zero();
#pragma GCC unroll 8
    for (int i = 0; i < N; ++i) y(i, row_of_[i]) = 1.0;
#pragma GCC unroll 8
    for (int k = 0; k < N; ++k) {
#pragma GCC unroll 8
      for (int i = k + 1; i < N; ++i) y.row(i) -= lu_(i, k) * y.row(k);
    }
#pragma GCC unroll 8
    for (int k = N - 1; k >= 0; --k) {
#pragma GCC unroll 8
      for (int j = k + 1; j < N; ++j) y.row(k) -= lu_(k, j) * y.row(j);
      y.row(k) *= inverse_diagonal_[k];
    }
    return y;
  }

 private:
  Matrix lu_;
  std::array<int, N> row_of_;  // row i of L U is row row_of_[i] of the matrix
  std::array<double, N> inverse_diagonal_;
};

// M = c I - J for a system that is translation invariant or not (see the file comment).
template <bool kTranslationInvariant>
class StageMatrix {
 public:
  using Jacobian = Eigen::Matrix<double, 7, 7>;

  void Factor(const Jacobian& jac, double c) {
    if constexpr (kTranslationInvariant) {
      lu_.Factor(c * Block::Identity() - jac.bottomRightCorner<5, 5>());
      position_by_motion_ = jac.topRightCorner<2, 5>();
      inverse_c_ = 1.0 / c;
    } else {
      lu_.Factor(c * Block::Identity() - jac);
    }
    inverse_ = lu_.Inverse();
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
  FixedSizeLu<kBlockSize> lu_;
  Block inverse_;
  Eigen::Matrix<double, 2, 5> position_by_motion_;  // J_pu
  double inverse_c_ = 0.0;
};

}  // namespace billiard::physics
