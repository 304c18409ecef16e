// The finished runs of this session, newest last, kept so plots can overlay them (e.g. 20 vs 100
// segments). Each run's label says what differs from the run before it of the same scenario.
#pragma once

#include <deque>

#include "run/run_controller.hpp"

namespace maris::ui {

class RunHistory {
 public:
  explicit RunHistory(std::size_t capacity = 8) : capacity_(capacity) {}

  // Adds a run, labels it (unless `keep_label`: a study's case comes named) and drops the oldest
  // beyond capacity. With the scene's `schema` the label names parameters as the editor does, with units.
  // Returns the stored record.
  const RunRecord& add(RunRecord record, bool keep_label = false, const Schema* schema = nullptr);
  const std::deque<RunRecord>& runs() const { return runs_; }
  const RunRecord* latest() const { return runs_.empty() ? nullptr : &runs_.back(); }
  const RunRecord* find(quint64 id) const;
  void clear() { runs_.clear(); }

 private:
  std::size_t capacity_;
  std::deque<RunRecord> runs_;
};

// Runs of one scenario (same scene and name): their tables' columns mean the same, so they may share a plot or
// a CSV. Runs of two scenarios of one scene may not (probe 3 at s = 75 m in one, 375 m in the other).
bool sameScenario(const Scenario& a, const Scenario& b);

// "segment count = 100, direction = 1.571 rad" for the leaf values that differ between two
// parameter objects (at most `max_items`, then "…"): each parameter by its editor label, numbers to 4
// significant digits with the schema's unit (when `schema` is given and knows the path).
QString parameterDifference(const Json& before, const Json& after, int max_items = 3, const Schema* schema = nullptr);

}  // namespace maris::ui
