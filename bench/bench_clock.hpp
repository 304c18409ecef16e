// CPU clocks for the work–precision benchmarks: unlike wall time they do not count the time other
// processes hold the (shared, two-core) machine.
#pragma once

#include <time.h>

namespace maris::bench {

// This thread only: for single-threaded work timed in a program that also runs other threads (the
// GUI build's plot tool, a sweep running beside it).
inline double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The whole process, all threads: for solvers that run in parallel (ship sweeps, seismic runs).
inline double processCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace maris::bench
