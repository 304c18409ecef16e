// The colour bar's numbers: ticks on a 1–2–5 grid, zero printed as 0 (never 4.86e-26), labels that print each
// tick exactly without exponents in the everyday range, and engineering units (27 MPa, not 2.7e+07 Pa).
#include <cstdio>
#include <string>
#include <vector>

#include <QtTest>

#include "view3d/color_bar_scale.hpp"

using namespace maris::ui;

namespace {

std::vector<std::string> labels(const ColorBarScale& s) {
  std::vector<std::string> out;
  for (double t : s.ticks) {
    char text[64];
    std::snprintf(text, sizeof text, s.label_format.c_str(), t);
    out.emplace_back(text);
  }
  return out;
}

std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : " ") + s;
  return out;
}

}  // namespace

class ColorBarTest : public QObject {
  Q_OBJECT
 private slots:
  void ticksLieOnAOneTwoFiveGrid() {
    // The odd values of an automatic 5-label bar over [-0.0126, 0.0399] become a 0.01 grid with an exact zero.
    const auto ticks = niceTicks(-0.0126, 0.0399, 5);
    QCOMPARE(static_cast<int>(ticks.size()), 5);
    for (std::size_t i = 0; i < ticks.size(); ++i) QVERIFY(std::abs(ticks[i] - (-0.01 + 0.01 * i)) < 1e-15);
    QCOMPARE(ticks[1], 0.0);
    // Every step is 1, 2 or 5 times a power of ten, for ranges over many decades.
    for (double lo : {-3.3e-7, 0.0, 12.0, 1.7e5})
      for (double width : {1e-6, 0.37, 8.0, 2.4e3, 9.9e8}) {
        const auto t = niceTicks(lo, lo + width, 5);
        QVERIFY2(t.size() >= 3 && t.size() <= 11, qPrintable(QString::number(t.size())));
        const double step = t[1] - t[0];
        const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
        // (the step is read back as a difference of ticks: relative rounding up to 1e-4 at 1.7e5 ± 1e-6)
        QVERIFY2(std::abs(mantissa - 1) < 1e-3 || std::abs(mantissa - 2) < 1e-3 || std::abs(mantissa - 5) < 1e-3,
                 qPrintable(QString::number(step)));
        QVERIFY(t.front() >= lo - 1e-9 * step && t.back() <= lo + width + 1e-9 * step);
      }
  }

  void zeroPrintsAsZero() {
    // A stress that is zero to rounding (4.86e-26 … 4.0e-7 Pa) reads 0, 0.1 µPa steps: never 4.86e-26.
    const ColorBarScale s = colorBarScale(4.86e-26, 4.0e-7, "Pa");
    QCOMPARE(s.ticks.front(), 0.0);
    QCOMPARE(labels(s).front(), std::string("0"));
    const ColorBarScale plain = colorBarScale(0.0, 0.0399, "-");
    QCOMPARE(joined(labels(plain)), std::string("0 0.01 0.02 0.03"));
  }

  void labelsNeedNoExponentInTheEverydayRange() {
    QCOMPARE(joined(labels(colorBarScale(100, 140, "s"))), std::string("100 110 120 130 140"));
    QCOMPARE(joined(labels(colorBarScale(-2.5, 12.5, "deg"))), std::string("0 5 10"));
    const auto fine = labels(colorBarScale(0.95, 1.05, "-"));
    QCOMPARE(joined(fine), std::string("0.96 0.98 1 1.02 1.04"));
  }

  void engineeringUnits() {
    const ColorBarScale stress = colorBarScale(0.0, 2.7e7, "Pa");  // bending stress of a riser
    QCOMPARE(stress.unit, std::string("MPa"));
    QCOMPARE(stress.factor, 1e-6);
    QCOMPARE(joined(labels(stress)), std::string("0 5 10 15 20 25"));
    QCOMPARE(colorBarScale(0.0, 2e6, "N").unit, std::string("MN"));      // top tension
    QCOMPARE(colorBarScale(0.0, 1e4 * 1.5, "N").unit, std::string("kN")); // horizontal top force
    QCOMPARE(colorBarScale(0.0, 4.0, "Pa").unit, std::string("Pa"));     // torsional stress stays in Pa
    QCOMPARE(colorBarScale(0.0, 5000.0, "N").unit, std::string("N"));    // four digits read well
    QCOMPARE(colorBarScale(-0.02, 0.02, "m").unit, std::string("mm"));   // 20 mm of motion
    QCOMPARE(colorBarScale(0.0, 150.0, "m").unit, std::string("m"));
    QCOMPARE(colorBarScale(0.0, 3e5, "rad/s").unit, std::string("rad/s"));  // no prefixes for other units
  }
};

QTEST_MAIN(ColorBarTest)
#include "test_color_bar.moc"
