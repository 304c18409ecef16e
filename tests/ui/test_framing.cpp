// The 3D view frames each model: the results of every built-in scenario, shown in a fresh view and then in a
// view that showed another model before, put the model's bounding box (with the water and sea-bed planes drawn
// with it) wholly inside the picture and fill most of it; a model of another size is framed anew, the same
// model again keeps the user's camera. Needs an X server with OpenGL (run under xvfb-run).
#include <algorithm>
#include <array>
#include <memory>

#include <QtTest>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include "catalog.hpp"
#include "core/run_context.hpp"
#include "example_runs.hpp"
#include "test_scene.hpp"
#include "ui_test_support.hpp"
#include "view3d/scene_view.hpp"
#include "view3d/vtk_gl_widget.hpp"

using namespace maris;
using namespace maris::ui;

namespace {

// Nothing cut off: every projected corner inside the view, which spans [-1, 1] (a hair of slack for rounding).
constexpr double kInside = 1.0 + 1e-6;
// Fills most of the view: the box spans at least 60 % of the width or of the height.
constexpr double kFilled = 0.6;

double span(const std::array<double, 4>& e) { return std::max(e[1] - e[0], e[3] - e[2]) / 2.0; }

QString describe(const std::array<double, 4>& e) {
  return QStringLiteral("x [%1, %2], y [%3, %4]").arg(e[0], 0, 'f', 3).arg(e[1], 0, 'f', 3).arg(e[2], 0, 'f', 3).arg(e[3], 0, 'f', 3);
}

void expectFramed(SceneView& view, const QString& what) {
  QCoreApplication::processEvents();
  const auto e = view.projectedModelExtent();
  QVERIFY2(e[0] >= -kInside && e[1] <= kInside && e[2] >= -kInside && e[3] <= kInside,
           qPrintable(what + QStringLiteral(": cut off, ") + describe(e)));
  QVERIFY2(span(e) >= kFilled, qPrintable(what + QStringLiteral(": too small, ") + describe(e)));
}

std::shared_ptr<const Results> runBuiltin(const BuiltinScenario& b) {
  RunContext context({}, nullptr);
  return std::make_shared<const Results>(runScenario(requireScene(b.scenario.scene), b.scenario, context));
}

}  // namespace

class FramingTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { test::isolateSettings(); }

  void everyBuiltInScenarioIsFramed() {
    SceneView reused;  // shows every model in turn, as the application's one view does
    reused.resize(900, 600);
    reused.show();
    QVERIFY(QTest::qWaitForWindowExposed(&reused));
    int shown = 0;
    for (const auto& b : test::uiTestExamples()) {  // under the sanitizers each scene's main example, shortened
      const auto results = runBuiltin(b);
      if (results->view.empty()) continue;
      ++shown;
      const QString name = QString::fromStdString(b.id);
      SceneView fresh;
      fresh.resize(900, 600);
      fresh.show();
      QVERIFY(QTest::qWaitForWindowExposed(&fresh));
      fresh.showResults(results);
      expectFramed(fresh, name + QStringLiteral(" (new view)"));
      reused.showResults(results);
      expectFramed(reused, name + QStringLiteral(" (after the previous scenario)"));
      test::keepScreenshot(reused.renderImage(900, 600), QStringLiteral("framing_") + name);
    }
    QVERIFY(shown >= 6);
  }

  void anotherSizeIsFramedAnewTheSameModelKeepsTheUsersCamera() {
    SceneView view;
    view.resize(800, 600);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.showResults(std::make_shared<const Results>(test::verticalTubeResults(100.0, 0.25)));
    expectFramed(view, QStringLiteral("100 m tube"));
    // A 500 m tube after the 100 m one: only its top would show in the old framing.
    view.showResults(std::make_shared<const Results>(test::verticalTubeResults(500.0, 0.25)));
    expectFramed(view, QStringLiteral("500 m tube after 100 m"));
    // Then a 150 m one: it would be tiny in the 500 m framing.
    view.showResults(std::make_shared<const Results>(test::verticalTubeResults(150.0, 0.25)));
    expectFramed(view, QStringLiteral("150 m tube after 500 m"));

    // The user zooms in; the same model again (a rerun) keeps that camera.
    emit view.glWidget()->cameraMovedByUser();
    vtkCamera* camera = view.glWidget()->renderer()->GetActiveCamera();
    camera->Zoom(2.0);
    std::array<double, 3> before{};
    camera->GetPosition(before.data());
    const double scale = camera->GetViewAngle();
    view.showResults(std::make_shared<const Results>(test::verticalTubeResults(150.0, 0.25)));
    view.resize(700, 600);  // nor does a resize override the user's camera
    QCoreApplication::processEvents();
    std::array<double, 3> after{};
    camera->GetPosition(after.data());
    QCOMPARE(camera->GetViewAngle(), scale);
    for (int i = 0; i < 3; ++i) QCOMPARE(after[i], before[i]);
    // Reset camera frames it again.
    view.resetCamera();
    expectFramed(view, QStringLiteral("after Reset camera"));
  }

  void aResizedViewIsFramedAgain() {
    SceneView view;
    view.resize(300, 900);  // tall and narrow first: a wide model is fitted to the narrow width
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    Results wide = test::verticalTubeResults(200.0, 0.5);
    for (auto& p : wide.view.frames[0].shapes[0].points) std::swap(p.x(), p.z());  // horizontal, 200 m along x
    view.showResults(std::make_shared<const Results>(wide));
    expectFramed(view, QStringLiteral("horizontal tube, tall view"));
    view.resize(1200, 400);
    expectFramed(view, QStringLiteral("horizontal tube, after a resize to a wide view"));
  }
};

QTEST_MAIN(FramingTest)
#include "test_framing.moc"
