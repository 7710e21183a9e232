// The assignment against brute force over every permutation.
#include "estimator/assignment.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace billiard::estimator {
namespace {

// Total cost of an assignment, counting an unassigned row of the square problem as `forbidden`.
double Total(const Eigen::MatrixXd& cost, const std::vector<int>& assigned, double forbidden) {
  double total = 0.0;
  int pairs = 0;
  for (std::size_t i = 0; i < assigned.size(); ++i) {
    if (assigned[i] >= 0) {
      total += cost(i, assigned[i]);
      ++pairs;
    }
  }
  const int n = static_cast<int>(std::max(cost.rows(), cost.cols()));
  return total + (n - pairs) * forbidden;
}

TEST(Assignment, MatchesBruteForceOnRandomMatrices) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const int rows = 1 + trial % 6, cols = 1 + (trial / 6) % 6;
    const double forbidden = 0.8;
    const Eigen::MatrixXd cost = Eigen::MatrixXd::NullaryExpr(rows, cols, [&] { return u(rng); });
    const std::vector<int> assigned = AssignMinimumCost(cost, forbidden);
    // Every column at most once, no forbidden pair.
    std::vector<int> used;
    for (int i = 0; i < rows; ++i) {
      if (assigned[i] < 0) continue;
      EXPECT_LT(cost(i, assigned[i]), forbidden);
      used.push_back(assigned[i]);
    }
    std::sort(used.begin(), used.end());
    EXPECT_EQ(std::adjacent_find(used.begin(), used.end()), used.end());
    // Brute force over the square problem's permutations.
    const int n = std::max(rows, cols);
    std::vector<int> perm(n);
    std::iota(perm.begin(), perm.end(), 0);
    double best = 1e300;
    do {
      double total = 0.0;
      for (int i = 0; i < n; ++i) {
        total += (i < rows && perm[i] < cols) ? std::min(cost(i, perm[i]), forbidden) : forbidden;
      }
      best = std::min(best, total);
    } while (std::next_permutation(perm.begin(), perm.end()));
    EXPECT_NEAR(Total(cost, assigned, forbidden), best, 1e-12) << rows << "x" << cols;
  }
}

TEST(Assignment, PrefersTheGlobalOptimumToGreedyNearest) {
  // Track 0 is nearest to detection 0, but taking it leaves track 1 with a far one.
  Eigen::MatrixXd cost(2, 2);
  cost << 1.0, 2.0, 1.5, 9.0;
  const std::vector<int> assigned = AssignMinimumCost(cost, 100.0);
  EXPECT_EQ(assigned[0], 1);
  EXPECT_EQ(assigned[1], 0);
}

}  // namespace
}  // namespace billiard::estimator
