#include "ship/resistance_sweep.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace maris::ship {

std::vector<std::vector<WaveResistance>> waveResistanceSweep(const std::vector<WaveResistanceCurve>& curves,
                                                             const std::vector<double>& speeds, double gravity,
                                                             double density, int threads, RunContext* context,
                                                             const std::string& stage,
                                                             const SweepObserver& observe) {
  const std::size_t n = speeds.size();
  std::vector<std::vector<WaveResistance>> out(curves.size(), std::vector<WaveResistance>(n));
  if (n == 0 || curves.empty()) return out;
  unsigned count = threads > 0 ? static_cast<unsigned>(threads) : std::max(1u, std::thread::hardware_concurrency());
  count = std::min<unsigned>(count, static_cast<unsigned>(n));

  // Shared state, all guarded by `mutex`: the next speed to take, the finished rows, the first error.
  std::mutex mutex;
  std::condition_variable row_done;
  std::size_t next = 0, done = 0;
  unsigned running = count;
  std::vector<bool> finished(n, false);
  std::exception_ptr first_error;

  // Dynamic scheduling: speeds differ in cost by orders of magnitude (low Fn needs many more λ panels).
  // A row is computed into locals and published under the lock, so the coordinator never reads a half-written row.
  auto work = [&] {
    try {
      std::vector<std::unique_ptr<KochinFunction>> kochin;
      for (const auto& curve : curves) kochin.push_back(curve.make_kochin());
      std::vector<WaveResistance> row(curves.size());
      for (;;) {
        std::size_t i;
        {
          std::lock_guard<std::mutex> lock(mutex);
          if (first_error || next >= n) break;
          i = next++;
        }
        for (std::size_t c = 0; c < curves.size(); ++c)
          row[c] = michellWaveResistance(*kochin[c], speeds[i], gravity, density, curves[c].settings, context);
        std::lock_guard<std::mutex> lock(mutex);
        for (std::size_t c = 0; c < curves.size(); ++c) out[c][i] = row[c];
        finished[i] = true;
        ++done;
        row_done.notify_one();
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!first_error) first_error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(mutex);
    --running;
    row_done.notify_one();
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < count; ++t) pool.emplace_back(work);

  // Coordinator: progress after every finished row; partial results when wanted (built outside the lock from
  // a copy, so the workers go on meanwhile). An exception here (a callback's) stops the workers like theirs.
  try {
    std::size_t reported = 0;
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
      row_done.wait(lock, [&] { return done > reported || running == 0; });
      if (first_error || (running == 0 && done == reported)) break;
      reported = done;
      const bool show = observe && context && context->wantsPartialResults();
      std::vector<std::vector<WaveResistance>> values;
      std::vector<bool> rows;
      if (show) values = out, rows = finished;
      lock.unlock();
      if (context) context->progress(static_cast<double>(reported) / n, stage);
      if (show) observe(values, rows);
      lock.lock();
    }
  } catch (...) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!first_error) first_error = std::current_exception();
  }
  for (auto& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
  return out;
}

std::vector<WaveResistance> waveResistanceSweep(const KochinFactory& make_kochin, const std::vector<double>& speeds,
                                                double gravity, double density, const MichellSettings& settings,
                                                int threads, RunContext* context, const std::string& stage) {
  return std::move(waveResistanceSweep({{make_kochin, settings}}, speeds, gravity, density, threads, context, stage)
                       .front());
}

}  // namespace maris::ship
