// Minimum-cost assignment of rows to columns (the Hungarian method, Kuhn and Munkres), for
// matching detections to tracks: with balls passing close to each other, matching each track
// to its nearest detection in turn can swap two balls where the optimal assignment does not.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace billiard::estimator {

// For an n x m cost matrix, the column assigned to each row (-1 for none) that minimises the
// total cost over min(n, m) pairs. Pairs whose cost is at least `forbidden` are never made:
// their rows and columns stay unassigned.
std::vector<int> AssignMinimumCost(const Eigen::MatrixXd& cost, double forbidden);

}  // namespace billiard::estimator
