// The Rosenbrock stage matrix against Eigen's full-pivoting LU on general and on structured
// matrices, including ones that need row exchanges.
#include "sim/physics/stage_matrix.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <random>

#include "sim/physics/ball_dynamics.h"
#include "sim/physics/testing/test_support.h"

namespace billiard::physics {
namespace {

StateJacobian RandomMatrix(std::mt19937* rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  StateJacobian m;
  for (int i = 0; i < 7; ++i) {
    for (int j = 0; j < 7; ++j) m(i, j) = unit(*rng) * (j == 3 ? 1e5 : 1.0);  // pivots move
  }
  return m;
}

BallState Reference(const StateJacobian& jac, double c, const BallState& r) {
  return (c * StateJacobian::Identity() - jac).fullPivLu().solve(r);
}

TEST(PivotedInverse, InvertsLikeFullPivoting) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 100; ++trial) {
    const StateJacobian a = RandomMatrix(&rng);
    const StateJacobian exact = a.fullPivLu().inverse();
    EXPECT_LT((PivotedInverse<7>(a) - exact).norm(), 1e-9 * exact.norm()) << trial;
  }
}

// Without row exchanges the first pivot of this matrix is zero.
TEST(PivotedInverse, ExchangesRowsForAZeroPivot) {
  Eigen::Matrix3d a;
  a << 0, 2, 1,  //
      3, 1, 0,   //
      1, 0, 4;
  const Eigen::Matrix3d inverse = PivotedInverse<3>(a);
  EXPECT_LT((inverse * a - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_LT((a * inverse - Eigen::Matrix3d::Identity()).norm(), 1e-14);
}

TEST(StageMatrix, GeneralAndTranslationInvariantSolvesAgree) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 100; ++trial) {
    StateJacobian jac = RandomMatrix(&rng);
    const BallState r = RandomMatrix(&rng).col(1);
    const double c = std::pow(10.0, trial % 8 - 2);
    StageMatrix<false> general;
    general.Invert(jac, c);
    const BallState exact = Reference(jac, c, r);
    EXPECT_LT((general.Solve(r) - exact).norm(), 1e-9 * exact.norm()) << trial;
    jac.leftCols<2>().setZero();  // the dynamics ignore X and Y
    StageMatrix<true> structured;
    structured.Invert(jac, c);
    const BallState exact_structured = Reference(jac, c, r);
    EXPECT_LT((structured.Solve(r) - exact_structured).norm(), 1e-9 * exact_structured.norm())
        << trial;
  }
}

TEST(StageMatrix, TheBallIsTranslationInvariant) {
  const ModelParameters p = testing::PaperParameters();
  const BallDynamics<ApproximateFrictionModel> dynamics(p, {p.contact});
  static_assert(IsTranslationInvariant<BallDynamics<ApproximateFrictionModel>>::value);
  static_assert(!IsTranslationInvariant<testing::LinearSystem>::value);
  for (const BallState& s : testing::PaperFigureStates()) {
    BallState f;
    StateJacobian jac;
    dynamics.DerivativeAndJacobian(s, &f, &jac);
    EXPECT_EQ(jac.leftCols<2>().norm(), 0.0);
    BallState moved = s;
    moved.head<2>() += Eigen::Vector2d(0.7, -0.3);
    EXPECT_EQ(dynamics.Derivative(moved), f);
  }
}

}  // namespace
}  // namespace billiard::physics
