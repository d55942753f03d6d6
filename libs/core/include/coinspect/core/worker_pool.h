// A fixed set of threads that runs submitted jobs in submission order (the units' decisions of
// a tick, mission_agents.cpp). The caller waits on the futures; a job's exception reaches the
// caller through its future.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <thread>
#include <vector>

namespace coinspect::core {

class WorkerPool {
 public:
  // Starts `threads` >= 1 worker threads.
  explicit WorkerPool(size_t threads);
  ~WorkerPool();  // runs the jobs still queued, then joins
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  size_t threads() const { return workers_.size(); }

  // Queues `job`; a free worker takes the oldest queued job first.
  std::future<void> submit(std::function<void()> job);

  // Calls job(0) ... job(count - 1) on the workers, each exactly once, and returns when all have
  // returned; then rethrows the exception of the lowest index that threw, if any.
  void run(size_t count, const std::function<void(size_t)>& job);

  // The number of threads to use for `requested` (0: one per hardware thread, at least 1).
  static size_t resolve(size_t requested);

 private:
  void work();
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::packaged_task<void()>> queue_;
  bool stopping_ = false;
};

}  // namespace coinspect::core
