// OpenCV on one thread while an object lives: the benchmarks' budget is a core's, and their runs
// are the same whatever the machine's cores.
#pragma once

#include <opencv2/core/utility.hpp>

namespace billiard::bench {

class OneThread {
 public:
  OneThread() : threads_(cv::getNumThreads()) { cv::setNumThreads(1); }
  ~OneThread() { cv::setNumThreads(threads_); }
  OneThread(const OneThread&) = delete;
  OneThread& operator=(const OneThread&) = delete;

 private:
  int threads_;
};

}  // namespace billiard::bench
