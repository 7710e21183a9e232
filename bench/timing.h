// How the benchmarks time a run: wall clock on the calling thread, the median of batch means.
//
// A run of tens of microseconds is below what one clock reading resolves well and is disturbed by
// whatever else the machine does, so cheap runs are repeated in batches and each batch's mean is
// one sample; the median of the samples discards the batches an interruption landed in. A run
// that alone fills the budget is timed once (it is long enough to read, and repeating it would
// cost minutes over a suite).
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace billiard::bench {

struct TimingBudget {
  double total_us = 2000.0;  // wall time to spend on the repeats, the first run excluded
  int batches = 5;           // samples whose median is reported (odd: the median is one of them)
};

// Wall time of one call of `run` [us]: called once (warm-up, and the size of the batches), then
// in `budget.batches` batches that together take about `budget.total_us`; the median of the
// batch means.
template <class Run>
double MedianWallUs(Run&& run, const TimingBudget& budget = {}) {
  using Clock = std::chrono::steady_clock;
  const auto elapsed_us = [](Clock::time_point start) {
    return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
  };
  constexpr double kMaxRepeats = 5000.0;  // per batch: a run too cheap to read at all
  const Clock::time_point first = Clock::now();
  run();
  const double once_us = elapsed_us(first);
  if (once_us >= budget.total_us || budget.batches < 1) return once_us;
  const int repeats = static_cast<int>(
      std::clamp(budget.total_us / budget.batches / std::max(once_us, 1e-3), 1.0, kMaxRepeats));
  std::vector<double> samples(budget.batches);
  for (double& sample : samples) {
    const Clock::time_point start = Clock::now();
    for (int i = 0; i < repeats; ++i) run();
    sample = elapsed_us(start) / repeats;
  }
  const auto median = samples.begin() + samples.size() / 2;
  std::nth_element(samples.begin(), median, samples.end());
  return *median;
}

}  // namespace billiard::bench
