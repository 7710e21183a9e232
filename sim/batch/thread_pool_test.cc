#include "sim/batch/thread_pool.h"

#include <gtest/gtest.h>

#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace billiard::batch {
namespace {

TEST(ThreadPool, ResultIIsJobIsWhateverTheThreadCount) {
  for (int threads : {1, 2, 4, 7}) {
    ThreadPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    const auto results = pool.Map(1000, [](std::size_t i) { return i * i; });
    ASSERT_EQ(results.size(), 1000u);
    for (std::size_t i = 0; i < results.size(); ++i) {
      ASSERT_TRUE(results[i].ok()) << i;
      EXPECT_EQ(*results[i].value, i * i);
    }
  }
}

TEST(ThreadPool, AThrowingJobFailsAloneWithItsMessage) {
  ThreadPool pool(3);
  const auto results = pool.Map(50, [](std::size_t i) -> int {
    if (i % 10 == 3) throw std::runtime_error("job " + std::to_string(i) + " failed");
    if (i == 7) throw 42;
    return static_cast<int>(i);
  });
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (i % 10 == 3) {
      EXPECT_FALSE(results[i].ok());
      EXPECT_EQ(results[i].error, "job " + std::to_string(i) + " failed");
    } else if (i == 7) {
      EXPECT_FALSE(results[i].ok());
      EXPECT_NE(results[i].error.find("other than a std::exception"), std::string::npos);
    } else {
      ASSERT_TRUE(results[i].ok()) << i << ": " << results[i].error;
      EXPECT_EQ(*results[i].value, static_cast<int>(i));
      EXPECT_TRUE(results[i].error.empty());
    }
  }
}

TEST(ThreadPool, RunsBatchAfterBatchAndAnEmptyOne) {
  ThreadPool pool(2);
  EXPECT_TRUE(pool.Map(0, [](std::size_t i) { return i; }).empty());
  for (int batch = 0; batch < 200; ++batch) {
    const auto results =
        pool.Map(3, [batch](std::size_t i) { return batch + static_cast<int>(i); });
    for (std::size_t i = 0; i < 3; ++i) ASSERT_EQ(*results[i].value, batch + static_cast<int>(i));
  }
}

TEST(ThreadPool, SpreadsTheJobsOverItsThreads) {
  ThreadPool pool(2);
  // Each job waits until two different threads have started one: the batch ends only if the
  // pool runs two jobs at once.
  std::mutex mutex;
  std::condition_variable both;
  std::vector<std::thread::id> seen;
  const auto results = pool.Map(2, [&](std::size_t) {
    std::unique_lock<std::mutex> lock(mutex);
    seen.push_back(std::this_thread::get_id());
    both.notify_all();
    both.wait(lock, [&] { return seen.size() == 2; });
    return seen.front() != seen.back();
  });
  EXPECT_TRUE(*results[0].value);
}

TEST(ThreadPool, TellsTheProgressOnceAJobAndInOrder) {
  ThreadPool pool(4);
  std::vector<std::size_t> told;
  pool.Map(
      100, [](std::size_t i) { return i; },
      [&](std::size_t done, std::size_t total) {
        EXPECT_EQ(total, 100u);
        told.push_back(done);
      });
  ASSERT_EQ(told.size(), 100u);
  for (std::size_t i = 0; i < told.size(); ++i) EXPECT_EQ(told[i], i + 1);
}

TEST(ThreadPool, RefusesABatchStartedFromItsOwnJob) {
  ThreadPool pool(2);
  const auto results = pool.Map(
      4, [&pool](std::size_t i) { return pool.Map(1, [i](std::size_t) { return i; }).size(); });
  for (const auto& r : results) {
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("thread pool that runs it"), std::string::npos) << r.error;
  }
  // The pool still works.
  EXPECT_EQ(*pool.Map(1, [](std::size_t) { return 5; })[0].value, 5);
}

TEST(ThreadPool, NeedsAThread) {
  EXPECT_THROW(ThreadPool(0), std::invalid_argument);
  EXPECT_GE(DefaultThreadCount(), 1);
}

}  // namespace
}  // namespace billiard::batch
