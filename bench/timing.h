// How the benchmarks and `billiard simulate` time a computation: warm, as a library caller sees
// it. The first run of a process pays for what the computation does not do again: page faults
// on fresh heap and stack, cold instruction and data caches, lazy binding of libm. A run that
// takes 40 us warm took 60-300 us cold (and `billiard simulate` reported the cold one), so a
// short computation is repeated until kWarmBudgetUs have passed and the mean of the repeats is
// its time; a long one (the integral model) is timed once.
#pragma once

#include <algorithm>
#include <chrono>

namespace billiard::bench {

inline constexpr double kWarmBudgetUs = 2000.0;

// Calls run() once (its result is the caller's), then, if that took less than kWarmBudgetUs,
// again until about kWarmBudgetUs have passed (at most 5000 times); returns the mean wall time
// of the repeats in microseconds, or of the first call when it was not repeated.
template <class Run>
double WarmWallMicroseconds(Run&& run) {
  using Clock = std::chrono::steady_clock;
  auto start = Clock::now();
  run();
  double us = std::chrono::duration<double, std::micro>(Clock::now() - start).count();
  const int repeats =
      static_cast<int>(std::clamp(kWarmBudgetUs / std::max(us, 1e-3), 1.0, 5000.0));
  if (repeats > 1) {
    start = Clock::now();
    for (int i = 0; i < repeats; ++i) run();
    us = std::chrono::duration<double, std::micro>(Clock::now() - start).count() / repeats;
  }
  return us;
}

}  // namespace billiard::bench
