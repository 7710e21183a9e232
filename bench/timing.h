// How the benchmarks time a run: wall clock on the calling thread, the median of batch means.
//
// A run of tens of microseconds is below what one clock reading resolves well and is disturbed by
// whatever else the machine does, so cheap runs are repeated in batches and each batch's mean is
// one sample; the median of the samples discards the batches an interruption landed in. A run
// that alone fills the budget is timed once (it is long enough to read, and repeating it would
// cost minutes over a suite). Runs to be compared with each other are timed interleaved, a batch
// of each in turn, so that a stretch of a busy machine slows them alike and their ratio holds.
#pragma once

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace billiard::bench {

struct TimingBudget {
  double total_us = 2000.0;  // wall time per run to spend on its repeats, the first call excluded
  int batches = 5;           // samples whose median is reported (odd: the median is one of them)
};

// Wall time of one call of each of `runs` [us]: each is called once (warm-up, and the size of its
// batches), then the runs take turns, one batch each, `budget.batches` times, the batches of a
// run together taking about `budget.total_us`; each run's median batch mean.
inline std::vector<double> MedianWallUsInterleaved(const std::vector<std::function<void()>>& runs,
                                                   const TimingBudget& budget = {}) {
  using Clock = std::chrono::steady_clock;
  const auto elapsed_us = [](Clock::time_point start) {
    return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
  };
  constexpr double kMaxRepeats = 5000.0;  // per batch: a run too cheap to read at all
  std::vector<double> wall_us(runs.size());
  std::vector<int> repeats(runs.size(), 0);  // 0: timed once
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Clock::time_point start = Clock::now();
    runs[i]();
    wall_us[i] = elapsed_us(start);
    if (wall_us[i] < budget.total_us && budget.batches > 0) {
      repeats[i] = static_cast<int>(std::clamp(
          budget.total_us / budget.batches / std::max(wall_us[i], 1e-3), 1.0, kMaxRepeats));
    }
  }
  std::vector<std::vector<double>> samples(runs.size());
  for (int b = 0; b < budget.batches; ++b) {
    for (std::size_t i = 0; i < runs.size(); ++i) {
      if (repeats[i] == 0) continue;
      const Clock::time_point start = Clock::now();
      for (int k = 0; k < repeats[i]; ++k) runs[i]();
      samples[i].push_back(elapsed_us(start) / repeats[i]);
    }
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (samples[i].empty()) continue;
    const auto median = samples[i].begin() + samples[i].size() / 2;
    std::nth_element(samples[i].begin(), median, samples[i].end());
    wall_us[i] = *median;
  }
  return wall_us;
}

// Wall time of one call of `run` [us], timed alone (MedianWallUsInterleaved).
inline double MedianWallUs(const std::function<void()>& run, const TimingBudget& budget = {}) {
  return MedianWallUsInterleaved({run}, budget)[0];
}

}  // namespace billiard::bench
