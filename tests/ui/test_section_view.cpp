// A 2-D model (a flat vertical section, as the seismic scene draws its wave field) in the 3D view: recognised by its
// geometry, seen square-on with an orthographic camera, its water, sea bed and boundary outlined in its plane; a
// 3-D model keeps the oblique perspective view. Under xvfb-run (OpenGL).
#include <QtTest>

#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include "test_scene.hpp"
#include "ui_test_support.hpp"
#include "view3d/scene_view.hpp"
#include "view3d/section_view.hpp"
#include "view3d/vtk_gl_widget.hpp"

using namespace maris;
using namespace maris::ui;

namespace {

// A section 40 m wide (x) and 20 m tall (z from −20 to 0) at y = 0, its scalar growing from 0 at the left to 1 at
// the right, with still water 10 m above the sea bed at z = 0.
Results sectionResults() {
  Shape3D s;
  s.kind = Shape3D::Kind::Surface;
  s.name = "section";
  s.grid_u = 21;
  s.grid_v = 11;
  for (int j = 0; j < s.grid_v; ++j)
    for (int i = 0; i < s.grid_u; ++i) {
      s.points.emplace_back(2.0 * i, 0.0, -20.0 + 2.0 * j);
      s.scalars.push_back(i / 20.0);
    }
  Results r;
  r.view.frames.push_back({0.0, {s}, {}});
  r.view.scalar_name = "magnitude";
  r.view.scalar_unit = "m";
  r.view.water_level_z = 10.0;
  r.view.seabed_z = 0.0;
  return r;
}

Bounds3D box(double x0, double x1, double y0, double y1, double z0, double z1) {
  Bounds3D b;
  b.add({x0, y0, z0});
  b.add({x1, y1, z1});
  return b;
}

int actorCount(SceneView& view) { return view.glWidget()->renderer()->GetActors()->GetNumberOfItems(); }

// Mean of blue − red (0 … 1 scale) over the saturated pixels of `area`: > 0 bluish, < 0 reddish.
double blueOverRed(const QImage& image, const QRect& area) {
  double sum = 0.0;
  long n = 0;
  for (int y = area.top(); y <= area.bottom(); ++y)
    for (int x = area.left(); x <= area.right(); ++x) {
      const QColor c = image.pixelColor(x, y);
      if (c.hsvSaturationF() < 0.3 || c.valueF() < 0.2) continue;
      sum += c.blueF() - c.redF();
      ++n;
    }
  return n ? sum / n : 0.0;
}

}  // namespace

class SectionViewTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { test::isolateSettings(); }

  // Which models are sections: flat across y (x–z plane) or across x (y–z plane), spanning the other two axes.
  void recognisesSections() {
    QCOMPARE(sectionNormalAxis(box(0, 40, 0, 0, -20, 0)), 1);
    QCOMPARE(sectionNormalAxis(box(0, 0, -5, 5, -20, 0)), 0);
    QCOMPARE(sectionNormalAxis(box(0, 40, 0, 1e-7, -20, 0)), 1);    // 2.2e-9 of the diagonal: flat
    QCOMPARE(sectionNormalAxis(box(0, 40, 0, 0.5, -20, 0)), -1);    // a tube's or a hull's thickness: a 3-D model
    QCOMPARE(sectionNormalAxis(box(0, 40, -10, 10, 0, 0)), -1);     // a horizontal surface (a wave pattern)
    QCOMPARE(sectionNormalAxis(box(0, 0, 0, 0, -100, 0)), -1);      // a vertical line
    QCOMPARE(sectionNormalAxis(Bounds3D{}), -1);
    QVERIFY(sectionViewDirection(1).isApprox(Eigen::Vector3d(0, -1, 0)));
    QVERIFY(sectionViewDirection(0).isApprox(Eigen::Vector3d(1, 0, 0)));
    // Water band and water line, sea-bed line, boundary; without water and sea bed the boundary alone.
    QCOMPARE(makeSectionOutlines(box(0, 40, 0, 0, -20, 0), 1, 10.0, 0.0).actors().size(), std::size_t(4));
    QCOMPARE(makeSectionOutlines(box(0, 40, 0, 0, -20, 0), 1, std::nullopt, std::nullopt).actors().size(), std::size_t(1));
  }

  // The section is seen square-on (the camera looks along +y, z up), orthographic, with the outlines drawn; its left
  // (low scalar) shows blue and its right red, so x runs to the right; the model fills the view. Then a 3-D model
  // (a vertical tube, 0.5 m thick) in the same view is seen in perspective again, with no outlines.
  void sectionSeenSquareOnThenThreeDAgain() {
    SceneView view;
    view.resize(640, 400);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.showResults(std::make_shared<Results>(sectionResults()));
    QTest::qWait(50);
    vtkCamera* camera = view.glWidget()->renderer()->GetActiveCamera();
    QVERIFY(camera->GetParallelProjection());
    double dop[3], up[3];
    camera->GetDirectionOfProjection(dop);
    camera->GetViewUp(up);
    QVERIFY2(std::abs(dop[0]) < 1e-9 && std::abs(dop[1] - 1.0) < 1e-9 && std::abs(dop[2]) < 1e-9,
             qPrintable(QStringLiteral("%1 %2 %3").arg(dop[0]).arg(dop[1]).arg(dop[2])));
    QVERIFY(std::abs(up[2] - 1.0) < 1e-9);
    QCOMPARE(actorCount(view), 1 + 4);  // the section and its four outlines

    const QImage image = view.glWidget()->grabFramebuffer();
    const int w = image.width(), h = image.height();
    // Along a row through the model (its lower part: the framed box is the model and the 10 m of water above
    // it), left of the colour bar's strip (the right ~22 %), the section's blue and red ends lie more than half the
    // picture's width apart (its white middle is not told from the background here).
    int first = -1, last = -1;
    for (int x = 0; x < w * 78 / 100; ++x) {
      const QColor c = image.pixelColor(x, h * 7 / 10);
      if (c.hsvSaturationF() > 0.3 && c.valueF() > 0.2) {
        if (first < 0) first = x;
        last = x;
      }
    }
    qInfo("section drawn from x = %d to %d of %d px", first, last, w);
    QVERIFY(first >= 0 && last - first > w / 2);
    // The colour map runs blue (0) – white – red (1): the section's left is blue, its right red: x to the right.
    const double left = blueOverRed(image, QRect(first, h * 55 / 100, (last - first) / 8, h / 4));
    const double right = blueOverRed(image, QRect(last - (last - first) / 8, h * 55 / 100, (last - first) / 8, h / 4));
    qInfo("blue - red: left %.2f, right %.2f", left, right);
    QVERIFY(left > 0.2);
    QVERIFY(right < -0.2);

    view.showResults(std::make_shared<Results>(test::verticalTubeResults(100.0, 0.25)));
    QTest::qWait(50);
    QVERIFY(!camera->GetParallelProjection());
    QCOMPARE(actorCount(view), 1);
  }

  // However narrow the view (the colour bar moved left to keep its title inside), the section ends left of the
  // bar's strip, and left of its title where it reaches up beside the title, and still fills a good part of the
  // view: the 40 m × 30 m section (water included), and a wide, low one (400 m × 30 m) that stays below the title.
  void aSectionIsFramedLeftOfTheColourBar() {
    const Results square = sectionResults();
    Results wide = sectionResults();
    for (Eigen::Vector3d& p : wide.view.frames[0].shapes[0].points) p.x() *= 10.0;
    for (const Results* results : {&square, static_cast<const Results*>(&wide)})
      for (const int width : {900, 460, 320}) {
        SceneView view;
        view.resize(width, 400);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.showResults(std::make_shared<Results>(*results));
        QTest::qWait(50);
        const auto e = view.projectedModelExtent();
        const SceneView::ColorBarExtent bar = view.colorBarExtent();  // fractions; the view spans [-1, 1]
        const double strip = 2.0 * bar.strip_left - 1.0, whole = 2.0 * bar.left - 1.0;
        const double title_bottom = 2.0 * bar.title_bottom - 1.0;
        const QString what = QStringLiteral("%1, %2 px: section x %3 … %4, y up to %5; bar from %6, strip from %7, "
                                            "title above %8")
                                 .arg(results == &wide ? "wide" : "square").arg(width).arg(e[0]).arg(e[1]).arg(e[3])
                                 .arg(whole).arg(strip).arg(title_bottom);
        qInfo("%s", qPrintable(what));
        // Clear of the strip (or at the least the view keeps for the section, its left half).
        QVERIFY2(e[1] <= strip + 1e-6 || e[1] <= 1e-6, qPrintable(what));
        if (e[3] > title_bottom) QVERIFY2(e[1] <= whole + 1e-6 || e[1] <= 1e-6, qPrintable(what));
        QVERIFY(e[0] >= -1.0 - 1e-6);
        QVERIFY2(e[1] - e[0] >= 0.8, qPrintable(what));
      }
  }
};

QTEST_MAIN(SectionViewTest)
#include "test_section_view.moc"
