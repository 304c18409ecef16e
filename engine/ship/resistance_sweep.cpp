#include "ship/resistance_sweep.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

namespace maris::ship {

std::vector<WaveResistance> waveResistanceSweep(const KochinFactory& make_kochin, const std::vector<double>& speeds,
                                                double gravity, double density, const MichellSettings& settings,
                                                int threads, RunContext* context, const std::string& stage) {
  const std::size_t n = speeds.size();
  std::vector<WaveResistance> out(n);
  if (n == 0) return out;
  unsigned count = threads > 0 ? static_cast<unsigned>(threads) : std::max(1u, std::thread::hardware_concurrency());
  count = std::min<unsigned>(count, static_cast<unsigned>(n));

  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex error_mutex;
  // Dynamic scheduling: speeds differ in cost by orders of magnitude (low Fn needs many more λ panels).
  auto work = [&](bool reports_progress) {
    try {
      auto kochin = make_kochin();
      for (std::size_t i = next++; i < n && !failed.load(); i = next++) {
        out[i] = michellWaveResistance(*kochin, speeds[i], gravity, density, settings, context);
        const std::size_t finished = ++done;
        if (reports_progress && context) context->progress(static_cast<double>(finished) / n, stage);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!first_error) first_error = std::current_exception();
      failed.store(true);
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < count; ++t) pool.emplace_back(work, false);
  work(true);
  for (auto& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
  return out;
}

}  // namespace maris::ship
