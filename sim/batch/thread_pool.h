// A fixed set of threads that runs N independent jobs and hands back their results in job order.
//
// Why: one shot's physics is sequential, but the benchmarks' references, shot selection and
// parameter identification run many independent shots, and on C cores a batch of them ends up to
// C times sooner. Threads are started once per pool, not per batch, so a pool can serve many
// small batches (the Jacobian columns of an identification, say).
//
// Deterministic: job i's result is stored at index i, whichever thread ran it and in whatever
// order, so a batch of jobs that share no mutable state (the physics has none) gives the same
// results, bit for bit, on 1 thread or 64.
//
// Failures stay per job: an exception that escapes job i becomes result i's error message, and
// the other jobs run on.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace billiard::batch {

// std::thread::hardware_concurrency(), or 1 where the machine does not say.
int DefaultThreadCount();

// One job's outcome: its value, or why it has none.
template <class T>
struct JobResult {
  std::optional<T> value;  // set when the job returned
  std::string error;       // the message of the exception that ended it, when it threw

  bool ok() const { return value.has_value(); }
};

// Told after each job ends, with the jobs ended so far and the batch's size; calls are one at a
// time, in the order jobs end, on whichever thread ended one. It must not throw.
using Progress = std::function<void(std::size_t done, std::size_t total)>;

class ThreadPool {
 public:
  // `threads` >= 1 (std::invalid_argument otherwise) run each batch: the caller's thread and
  // threads - 1 started here, which wait between batches.
  explicit ThreadPool(int threads = DefaultThreadCount());
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }

  // Runs job(i) for every i in [0, n) and returns once all have ended, result i being job(i)'s.
  // Jobs are handed out in index order as threads come free. Batches from several threads take
  // turns; a job that starts a batch on its own pool would wait for itself, and is refused
  // (std::logic_error, which becomes that job's error).
  template <class Job>
  auto Map(std::size_t n, Job&& job, const Progress& progress = nullptr)
      -> std::vector<JobResult<std::invoke_result_t<Job&, std::size_t>>> {
    using T = std::invoke_result_t<Job&, std::size_t>;
    static_assert(!std::is_void_v<T>, "a job returns its result");
    std::vector<JobResult<T>> results(n);
    std::mutex progress_mutex;
    std::size_t done = 0;
    ForEach(n, [&](std::size_t i) {
      try {
        results[i].value.emplace(job(i));
      } catch (const std::exception& e) {
        results[i].error = e.what();
      } catch (...) {
        results[i].error = "a job threw something other than a std::exception";
      }
      if (progress) {
        const std::lock_guard<std::mutex> lock(progress_mutex);
        progress(++done, n);
      }
    });
    return results;
  }

 private:
  struct Batch;

  // Calls body(i) once for every i in [0, n), on all the pool's threads; body must not throw.
  // Returns once every call has returned, without waiting for threads that took no job: on a
  // busy machine a worker may wake after the caller has done the whole batch.
  void ForEach(std::size_t n, const std::function<void(std::size_t)>& body);
  // Takes the batch's next index until none is left.
  void Work(Batch& batch);
  void WorkerLoop();

  std::vector<std::thread> workers_;
  std::mutex batch_mutex_;  // one batch at a time

  // The current batch, published under mutex_ with a new generation; a worker keeps its batch
  // alive while it looks at it.
  std::mutex mutex_;
  std::condition_variable wake_, finished_;
  std::uint64_t generation_ = 0;
  bool stopping_ = false;
  std::shared_ptr<Batch> batch_;
};

}  // namespace billiard::batch
