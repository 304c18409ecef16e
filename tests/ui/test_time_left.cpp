// The run panel's time-left estimate (TimeLeftEstimate) driven by a fake solver whose progress is a schedule of
// stages, each advancing its fraction linearly; the clock is the schedule's own, so nothing here waits or times.
// Expected values are closed forms of the schedule: at a constant pace r, (1 − f) / r seconds are left.
#include <QtTest>

#include <cmath>
#include <functional>
#include <vector>

#include "run/time_left.hpp"

using namespace maris::ui;

namespace {

struct Stage {
  QString name;
  double seconds;  // how long the stage runs
  double from, to;  // the fraction the solver reports at its start and at its end
};

// Feeds `estimate` the solver's reports every `step_s` from 0 up to `until_s` and returns the last estimate.
// `name_of` (optional) gives the stage text at a time, to model solvers that put changing detail after a ':'.
double feed(TimeLeftEstimate& estimate, const std::vector<Stage>& stages, double until_s, double step_s = 0.1,
            const std::function<QString(const Stage&, double)>& name_of = {}) {
  double last = -1.0;
  const int steps = static_cast<int>(std::lround(until_s / step_s));
  for (int k = 0; k <= steps; ++k) {
    const double t = k * step_s;
    double start = 0.0;
    for (const Stage& s : stages) {
      if (t <= start + s.seconds + 1e-12) {
        const double f = s.from + (s.to - s.from) * (t - start) / s.seconds;
        last = estimate.update(t, f, name_of ? name_of(s, t - start) : s.name);
        break;
      }
      start += s.seconds;
    }
  }
  return last;
}

}  // namespace

class TestTimeLeft : public QObject {
  Q_OBJECT

 private slots:
  // A quick early stage counted in the same fraction as the long one after it (free field 0–5 % in 10 s, then
  // finite-element runs at 3 %/s): once the long stage has run 2 s, its own pace alone sets the estimate. Whole-run
  // extrapolation (elapsed × (1 − f) / f) would say 37.1 s at t = 20 s, 1.7× the 21.7 s left.
  void earlyStageDoesNotSetThePace() {
    const std::vector<Stage> run{{"free field", 10.0, 0.0, 0.05}, {"finite-element runs", 95.0 / 3.0, 0.05, 1.0}};
    for (double t : {12.5, 20.0, 30.0}) {
      TimeLeftEstimate estimate;
      const double f = 0.05 + 0.03 * (t - 10.0);
      QVERIFY2(qAbs(feed(estimate, run, t) - (1.0 - f) / 0.03) < 1e-6 * (1.0 - f) / 0.03,
               qPrintable(QStringLiteral("t = %1 s").arg(t)));
    }
  }

  // A stage that counts from zero again (statics to 95 % in 10 s, then the time integration from 0 at 10 %/s):
  // no estimate for its first 2 s, then (1 − 0.3) / 0.1 = 7 s at 3 s into it (whole-run extrapolation: 30.3 s).
  void restartedStageStartsItsOwnEstimate() {
    const std::vector<Stage> run{{"statics", 10.0, 0.0, 0.95}, {"time integration", 10.0, 0.0, 1.0}};
    TimeLeftEstimate early;
    QCOMPARE(feed(early, run, 11.5), -1.0);
    TimeLeftEstimate later;
    QVERIFY(qAbs(feed(later, run, 13.0) - 7.0) < 1e-6);
  }

  // Nothing is said in the first 2 s of a run: the pace of its first moments is not a forecast.
  void noEstimateBeforeTheMinimumWindow() {
    const std::vector<Stage> run{{"time integration", 10.0, 0.0, 1.0}};
    TimeLeftEstimate estimate;
    QCOMPARE(feed(estimate, run, 1.9), -1.0);
    TimeLeftEstimate after;
    QVERIFY(qAbs(feed(after, run, 2.0) - 8.0) < 1e-6);
  }

  // One stage whose pace doubles halfway (1 %/s for 50 s, then 2 %/s): at t = 70 s, 5 s are left at the new pace.
  // The window (30 % of the stage's 70 s = 21 s) reaches 1 s into the slow part, so the estimate is 5.12 s,
  // within 3 % of the truth; whole-run extrapolation says 7.8 s.
  void followsARecentChangeOfPace() {
    const std::vector<Stage> run{{"time integration", 50.0, 0.0, 0.5}, {"time integration", 25.0, 0.5, 1.0}};
    TimeLeftEstimate estimate;
    const double left = feed(estimate, run, 70.0);
    QVERIFY2(qAbs(left - 5.0) < 0.03 * 5.0, qPrintable(QString::number(left)));
  }

  // A stage whose text carries changing detail after ':' ("frequency sweep: case 3") is one stage: with a case
  // every 0.5 s and the fraction at 10 %/s, 7 s are left at t = 3 s.
  void detailAfterAColonIsTheSameStage() {
    const std::vector<Stage> run{{"frequency sweep", 10.0, 0.0, 1.0}};
    TimeLeftEstimate estimate;
    const double left = feed(estimate, run, 3.0, 0.1, [](const Stage& s, double t) {
      return s.name + QStringLiteral(": case %1").arg(static_cast<int>(t / 0.5) + 1);
    });
    QVERIFY2(qAbs(left - 7.0) < 1e-6, qPrintable(QString::number(left)));
    QCOMPARE(stageName(QStringLiteral(" statics : dynamic relaxation")), QStringLiteral("statics"));
  }

  // A solver that stops advancing (a long call it cannot report from) gets no estimate, rather than one that
  // pretends the pace is known; a finished stage needs none.
  void stalledOrFinishedHasNone() {
    const std::vector<Stage> run{{"time integration", 5.0, 0.0, 0.5}, {"modal analysis", 10.0, 0.5, 0.5}};
    TimeLeftEstimate stalled;
    QCOMPARE(feed(stalled, run, 15.0), -1.0);
    TimeLeftEstimate finished;
    QCOMPARE(feed(finished, {{"time integration", 5.0, 0.0, 1.0}}, 5.0), -1.0);
  }

  // restart() forgets the previous run: the new one has no estimate for its first 2 s.
  void restartForgetsThePreviousRun() {
    TimeLeftEstimate estimate;
    feed(estimate, {{"time integration", 10.0, 0.0, 0.9}}, 10.0);
    estimate.restart();
    QCOMPARE(estimate.update(100.0, 0.5, QStringLiteral("time integration")), -1.0);
    QCOMPARE(estimate.update(101.0, 0.6, QStringLiteral("time integration")), -1.0);
  }
};

QTEST_GUILESS_MAIN(TestTimeLeft)
#include "test_time_left.moc"
