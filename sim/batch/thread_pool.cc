#include "sim/batch/thread_pool.h"

#include <atomic>
#include <stdexcept>

namespace billiard::batch {

namespace {

// The pool whose batch this thread is working on, if any: a batch started from inside one of
// its own jobs would wait for the job that waits for it.
thread_local const ThreadPool* working_for = nullptr;

}  // namespace

int DefaultThreadCount() {
  const unsigned cores = std::thread::hardware_concurrency();
  return cores == 0 ? 1 : static_cast<int>(cores);
}

ThreadPool::ThreadPool(int threads) {
  if (threads < 1) throw std::invalid_argument("a thread pool needs at least one thread");
  workers_.reserve(threads - 1);
  for (int i = 1; i < threads; ++i) workers_.emplace_back([this] { WorkerLoop(); });
}

ThreadPool::~ThreadPool() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

struct ThreadPool::Batch {
  const std::function<void(std::size_t)>* body = nullptr;
  std::size_t size = 0;
  std::atomic<std::size_t> next{0};  // the next index to hand out
  std::atomic<std::size_t> done{0};  // calls returned
};

void ThreadPool::ForEach(std::size_t n, const std::function<void(std::size_t)>& body) {
  if (working_for == this) {
    throw std::logic_error("a job started a batch on the thread pool that runs it");
  }
  const std::lock_guard<std::mutex> one_batch(batch_mutex_);
  const auto batch = std::make_shared<Batch>();
  batch->body = &body;
  batch->size = n;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    batch_ = batch;
    ++generation_;
  }
  wake_.notify_all();
  Work(*batch);
  std::unique_lock<std::mutex> lock(mutex_);
  finished_.wait(lock, [&] { return batch->done == n; });
  batch_.reset();
}

void ThreadPool::Work(Batch& batch) {
  working_for = this;
  for (std::size_t i; (i = batch.next.fetch_add(1)) < batch.size;) {
    (*batch.body)(i);
    if (batch.done.fetch_add(1) + 1 == batch.size) {
      const std::lock_guard<std::mutex> lock(mutex_);
      finished_.notify_all();
    }
  }
  working_for = nullptr;
}

void ThreadPool::WorkerLoop() {
  std::uint64_t seen = 0;
  for (;;) {
    std::shared_ptr<Batch> batch;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      batch = batch_;
    }
    if (batch) Work(*batch);
  }
}

}  // namespace billiard::batch
