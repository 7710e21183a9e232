#include "estimator/assignment.h"

#include <algorithm>
#include <limits>

namespace billiard::estimator {

std::vector<int> AssignMinimumCost(const Eigen::MatrixXd& cost, double forbidden) {
  const int rows = static_cast<int>(cost.rows()), cols = static_cast<int>(cost.cols());
  std::vector<int> assigned(rows, -1);
  if (rows == 0 || cols == 0) return assigned;
  // Square it: dummy rows and columns, and forbidden pairs, cost `forbidden` (finite, so the
  // method stays well defined); such pairs are dropped afterwards.
  const int n = std::max(rows, cols);
  Eigen::MatrixXd c = Eigen::MatrixXd::Constant(n, n, forbidden);
  c.topLeftCorner(rows, cols) = cost.cwiseMin(forbidden);

  // Shortest augmenting paths with potentials (1-based, column 0 a sentinel): O(n^3).
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0.0), v(n + 1, 0.0);
  std::vector<int> row_of(n + 1, 0), way(n + 1, 0);
  for (int i = 1; i <= n; ++i) {
    row_of[0] = i;
    int j0 = 0;
    std::vector<double> min_to(n + 1, inf);
    std::vector<bool> used(n + 1, false);
    do {
      used[j0] = true;
      const int i0 = row_of[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= n; ++j) {
        if (used[j]) continue;
        const double reduced = c(i0 - 1, j - 1) - u[i0] - v[j];
        if (reduced < min_to[j]) {
          min_to[j] = reduced;
          way[j] = j0;
        }
        if (min_to[j] < delta) {
          delta = min_to[j];
          j1 = j;
        }
      }
      for (int j = 0; j <= n; ++j) {
        if (used[j]) {
          u[row_of[j]] += delta;
          v[j] -= delta;
        } else {
          min_to[j] -= delta;
        }
      }
      j0 = j1;
    } while (row_of[j0] != 0);
    do {
      const int j1 = way[j0];
      row_of[j0] = row_of[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  for (int j = 1; j <= n; ++j) {
    const int i = row_of[j] - 1, col = j - 1;
    if (i < rows && col < cols && cost(i, col) < forbidden) assigned[i] = col;
  }
  return assigned;
}

}  // namespace billiard::estimator
