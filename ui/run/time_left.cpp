#include "run/time_left.hpp"

#include <algorithm>

namespace maris::ui {

QString stageName(const QString& stage) {
  const qsizetype colon = stage.indexOf(QLatin1Char(':'));
  return (colon < 0 ? stage : stage.left(colon)).trimmed();
}

void TimeLeftEstimate::restart() {
  samples_.clear();
  stage_name_.clear();
  stage_start_s_ = name_change_s_ = 0.0;
}

double TimeLeftEstimate::update(double now_s, double fraction, const QString& stage) {
  const QString name = stageName(stage);
  // A fraction going back is a stage counting from zero: nothing before it says anything about its pace.
  if (samples_.empty() || fraction < samples_.back().fraction - 1e-9) {
    samples_.clear();
    stage_start_s_ = name_change_s_ = now_s;
  } else if (name != stage_name_) {
    name_change_s_ = now_s;
  }
  stage_name_ = name;
  samples_.push_back({now_s, fraction});

  const double in_stage = now_s - stage_start_s_;
  if (fraction >= 1.0 || in_stage < settings_.min_window_s) return -1.0;
  const double window = std::clamp(settings_.window_share * in_stage, settings_.min_window_s, settings_.max_window_s);
  double window_start = now_s - window;
  // A renamed stage with a monotone fraction (free field 0–5 %, then finite-element runs 5–95 %) keeps the samples
  // across the change until the new stage has run for the minimum window; from then on only its own pace counts.
  if (name_change_s_ > window_start && now_s - name_change_s_ >= settings_.min_window_s) window_start = name_change_s_;

  // Samples older than the longest window are not needed again; keep the last one at or before the window's start.
  while (samples_.size() > 2 && samples_[1].t <= now_s - settings_.max_window_s) samples_.pop_front();
  auto first = std::upper_bound(samples_.begin(), samples_.end(), window_start,
                                [](double t, const Sample& s) { return t < s.t; });
  if (first != samples_.begin()) --first;  // the last sample at or before the window's start
  const Sample& from = *first;
  const double span = now_s - from.t, advance = fraction - from.fraction;
  if (span <= 0.0 || advance < settings_.min_advance) return -1.0;
  return (1.0 - fraction) * span / advance;
}

}  // namespace maris::ui
