// A library call that cannot be interrupted (a dense eigen solve), run so that a cancellation still takes
// effect within the latency every other stage keeps.
#pragma once

#include <chrono>
#include <future>
#include <thread>
#include <type_traits>
#include <utility>

#include "core/run_context.hpp"

namespace maris {

// Runs `work` on a thread of its own and waits for it, looking at the run's cancel flag every 10 ms. When the
// run is cancelled first, the thread is left to finish by itself (its result is discarded: the CPU stays busy
// for what remains of that one call, at most the run's estimated uninterruptible stretch) and RunCancelled is
// thrown at once. `work` must own everything it reads (capture by value): the caller's frame is gone when an
// abandoned thread ends. Exceptions from `work` reach the caller.
template <class Work>
std::invoke_result_t<Work> runAbandonable(RunContext& context, Work work) {
  using Value = std::invoke_result_t<Work>;
  std::packaged_task<Value()> task(std::move(work));
  std::future<Value> result = task.get_future();
  std::thread(std::move(task)).detach();  // the task's shared state outlives an abandoned wait
  while (result.wait_for(std::chrono::milliseconds(10)) != std::future_status::ready) context.throwIfCancelled();
  return result.get();
}

}  // namespace maris
