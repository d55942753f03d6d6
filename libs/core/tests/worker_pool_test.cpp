#include "coinspect/core/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <stdexcept>
#include <string>

namespace coinspect::core {

TEST(WorkerPool, EveryIndexRunsOnceOverManyBatches) {
  for (const size_t threads : {1u, 2u, 4u}) {
    WorkerPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    for (size_t count = 0; count < 40; ++count) {
      std::vector<int> runs(count, 0);
      pool.run(count, [&](size_t i) { ++runs[i]; });
      for (size_t i = 0; i < count; ++i)
        EXPECT_EQ(runs[i], 1) << threads << " threads, batch of " << count << ", index " << i;
    }
  }
}

TEST(WorkerPool, JobsRunOnSeveralThreadsAtOnce) {
  // Two jobs that each wait for the other to start can only finish on two threads.
  WorkerPool pool(2);
  std::atomic<int> started{0};
  std::set<std::thread::id> ids;
  std::mutex idsMutex;
  pool.run(2, [&](size_t) {
    {
      std::lock_guard<std::mutex> lock(idsMutex);
      ids.insert(std::this_thread::get_id());
    }
    ++started;
    while (started.load() < 2)
      std::this_thread::yield();
  });
  EXPECT_EQ(ids.size(), 2u);
  EXPECT_EQ(ids.count(std::this_thread::get_id()), 0u);  // the workers, not the caller
}

TEST(WorkerPool, SubmittedJobsReportThroughTheirFutures) {
  WorkerPool pool(1);
  int value = 0;
  auto set = pool.submit([&] { value = 42; });
  auto fail = pool.submit([] { throw std::runtime_error("failed job"); });
  set.get();
  EXPECT_EQ(value, 42);
  EXPECT_THROW(fail.get(), std::runtime_error);
}

TEST(WorkerPool, TheLowestFailingIndexIsRethrownAfterAllFinished) {
  WorkerPool pool(3);
  std::atomic<int> finished{0};
  try {
    pool.run(10, [&](size_t i) {
      ++finished;
      if (i == 7 || i == 3) throw std::runtime_error("job " + std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "job 3");
  }
  EXPECT_EQ(finished.load(), 10);
  // The pool is still usable.
  std::atomic<int> again{0};
  pool.run(5, [&](size_t) { ++again; });
  EXPECT_EQ(again.load(), 5);
}

TEST(WorkerPool, ResolveGivesAtLeastOneThread) {
  EXPECT_EQ(WorkerPool::resolve(3), 3u);
  EXPECT_GE(WorkerPool::resolve(0), 1u);
}

}  // namespace coinspect::core
