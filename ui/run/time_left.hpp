// Time left in a run, from the solver's own progress fraction and its rate over a recent window.
//
// Solvers report a fraction per stage ("statics", then "time integration" counting from zero again), and
// stages run at very different speeds (a quick free-field stage before minutes of finite-element steps,
// a statics solve before the time integration). Extrapolating the whole elapsed time over the whole fraction
// carries an early stage's pace into the estimate; here the rate is the fraction's advance over the last
// few seconds of the current stage, and the estimate is withheld until that window is long enough.
// Time comes in as an argument (any steady clock, seconds), so a test can drive it without waiting.
#pragma once

#include <deque>

#include <QString>

namespace maris::ui {

class TimeLeftEstimate {
 public:
  struct Settings {
    double min_window_s = 2.0;   // no estimate from less than this much of a stage's progress
    double window_share = 0.3;   // the window is this share of the stage's time so far (steadier on long stages)
    double max_window_s = 60.0;  // but never longer than this
    double min_advance = 0.005;  // the fraction must have advanced this much within the window
  };

  TimeLeftEstimate() = default;
  explicit TimeLeftEstimate(Settings settings) : settings_(settings) {}

  // Forgets everything (a new run).
  void restart();
  // The solver reports `fraction` (0…1) of `stage` at `now_s`. Returns the seconds until the fraction reaches 1
  // at its recent rate, or a negative value while no estimate is meaningful (too early in a stage, no advance,
  // finished). A fraction lower than the last one starts a new stage (the solver counts from zero again); so does
  // a new stage name, once it has run for the minimum window (a stage's name is its text before the first ':',
  // so "frequency sweep: n = 20" and "frequency sweep: n = 40" are one stage).
  double update(double now_s, double fraction, const QString& stage);

 private:
  struct Sample {
    double t;
    double fraction;
  };
  Settings settings_;
  std::deque<Sample> samples_;  // the current stage's reports, oldest first
  double stage_start_s_ = 0.0;  // when the current stage (or the run) began counting
  double name_change_s_ = 0.0;  // when the stage name last changed without the fraction going back
  QString stage_name_;
};

// A stage's name without its detail: the text before the first ':', trimmed.
QString stageName(const QString& stage);

}  // namespace maris::ui
