// Seeded uniform numbers that are the same on every standard library: std::mt19937_64 mapped to
// [0, 1) by hand (the standard distributions' algorithms are unspecified), for racks and for the
// seeded layouts of the tests and benchmarks.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace billiard::table {

class SeededUniform {
 public:
  explicit SeededUniform(std::uint64_t seed) : engine_(seed) {}
  // In [0, 1): the top 53 bits of a draw, scaled.
  double Next() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double Between(double lo, double hi) { return lo + (hi - lo) * Next(); }
  std::size_t Below(std::size_t n) { return static_cast<std::size_t>(Next() * n); }
  // A point in the disc of radius `radius` (not uniform in area; a rack needs only the bound).
  Eigen::Vector2d InDisc(double radius) {
    const double r = radius * Next();
    const double angle = 2 * M_PI * Next();
    return r * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  }
  // Fisher-Yates, with this generator (std::shuffle's use of the engine is unspecified).
  template <typename T>
  void Shuffle(std::vector<T>* items) {
    for (std::size_t i = items->size(); i > 1; --i) std::swap((*items)[i - 1], (*items)[Below(i)]);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace billiard::table
