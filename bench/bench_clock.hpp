// CPU time of the calling thread, for the work–precision benchmarks: unlike wall time it does not
// count the time other processes hold the (shared, two-core) machine, and unlike std::clock it does
// not count other threads of this process (the GUI build's or a parallel sweep's).
#pragma once

#include <time.h>

namespace maris::bench {

inline double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace maris::bench
