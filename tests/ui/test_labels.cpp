// What people read names no internal identifier: every built-in scenario of every scene is run, each of its plots
// drawn as the GUI draws it (fillPlot) and its title, tab title, axis titles and legend entries, and the labels of
// its scalars in the results dock, scanned for snake_case words ("c_wave_holtrop") and dotted parameter paths
// ("speed.froude_min"). The test fails listing every offender, and every plotted column or scalar whose scene
// declared no label (shown under the readable fallback made from the name).
#include <map>
#include <memory>
#include <regex>
#include <set>

#include <QtTest>
#include <qcustomplot.h>

#include "catalog.hpp"
#include "core/run_context.hpp"
#include "document/scenario_document.hpp"
#include "example_runs.hpp"
#include "plots/result_plot.hpp"
#include "ui_test_support.hpp"

using namespace maris;
using namespace maris::ui;

namespace {

// A snake_case identifier (two lower-case words of two or more letters joined by '_', so symbols such as C_W,
// σ_b, F_x pass) or a dotted path (two such words joined by '.').
bool looksInternal(const std::string& text) {
  static const std::regex internal(R"((^|[^A-Za-z0-9])[a-z][a-z0-9]+[_.][a-z][a-z0-9_.]+)");
  return std::regex_search(text, internal);
}

std::vector<std::string> plotTexts(QCustomPlot& plot) {
  std::vector<std::string> texts;
  for (int e = 0; e < plot.plotLayout()->elementCount(); ++e)
    if (auto* title = qobject_cast<QCPTextElement*>(plot.plotLayout()->elementAt(e)))
      texts.push_back(title->text().toStdString());
  for (QCPAxisRect* rect : plot.axisRects())
    for (QCPAxis* axis : rect->axes()) texts.push_back(axis->label().toStdString());
  for (int g = 0; g < plot.graphCount(); ++g) texts.push_back(plot.graph(g)->name().toStdString());
  return texts;
}

}  // namespace

class LabelsTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { test::isolateSettings(); }

  void looksInternalFindsIdentifiersNotSymbols() {
    for (const char* internal : {"c wave holtrop [c_wave_holtrop]", "must exceed speed.froude_min", "A_star_up_h1.11",
                                 "Envelope: displacement_amplitude"})
      QVERIFY2(looksInternal(internal), internal);
    for (const char* human : {"C_W Michell", "σ_b at probe 2 [MPa]", "A*/D, up, h* = 1.11", "Fn", "R_T [N]",
                              "S_Fx, float 1", "x/L = 0.25", "Along the riser at t = 12.5 s"})
      QVERIFY2(!looksInternal(human), human);
  }

  // Messages name fields by their paths (what a scenario file's author needs); the GUI shows them as the editor
  // names them, group ▸ label, a table's cell as a study names it (rows counted from 1). Words that are no
  // parameter of the scene stay.
  void messagesNameFieldsAsTheEditorDoes() {
    const Schema& ship = requireScene("ship").schema;
    QCOMPARE(withFieldNames("parameters.speed.froude_max = 0.1: must be greater than speed.froude_min = 0.2.", ship),
             QStringLiteral("Speed ▸ Last Froude number = 0.1: must be greater than Speed ▸ First Froude number = 0.2."));
    const Schema& riser = requireScene("riser").schema;
    QCOMPARE(withFieldNames("parameters.sections[1].outer_diameter = 0: must be > 0", riser),
             QStringLiteral("Outer diameter D_out of section row 2 = 0: must be > 0"));
    QCOMPARE(withFieldNames("output.probes[0].arc_length beyond geometry.length", riser),
             QStringLiteral("Output ▸ Arc length of probe row 1 beyond Geometry ▸ Length L"));
    QCOMPARE(withFieldNames("see docs/riser.md and solver.no_such_field", riser),
             QStringLiteral("see docs/riser.md and solver.no_such_field"));
    QVERIFY(!looksInternal(withFieldNames("parameters.speed.froude_min", ship).toStdString()));
  }

  void everyBuiltInScenarioShowsLabelsNotIdentifiers() {
    QStringList offenders, fallbacks;
    int texts = 0, declared = 0;
    std::set<std::string> seen_fallbacks;
    std::map<std::string, std::set<std::string>> unused_group_names;  // scene -> declared plot names no plot matched
    for (const auto& b : test::uiTestExamples()) {  // under the sanitizers each scene's main example, shortened
      const SceneDefinition& scene = requireScene(b.scenario.scene);
      if (!unused_group_names.count(scene.name))
        for (const PlotGroupSpec& g : scene.plot_groups) unused_group_names[scene.name].insert(g.plots.begin(), g.plots.end());
      RunContext context({}, nullptr);
      const Results results = runScenario(requireScene(b.scenario.scene), b.scenario, context);
      const QString where = QString::fromStdString(b.id);
      auto check = [&](const std::string& text, const QString& what) {
        ++texts;
        if (looksInternal(text)) offenders << QStringLiteral("%1, %2: \"%3\"").arg(where, what, QString::fromStdString(text));
      };
      for (const PlotSpec& spec : results.plots) {
        const QString plot_name = QString::fromStdString(spec.name);
        // A scene that declares plot groups puts every plot in one of them.
        int holders = 0;
        for (const PlotGroupSpec& g : scene.plot_groups)
          for (const std::string& name : g.plots)
            if (plotGroupHolds(PlotGroupSpec{g.title, {name}}, spec.name)) {
              holders += 1;
              unused_group_names[scene.name].erase(name);
            }
        QVERIFY2(scene.plot_groups.empty() || holders == 1,
                 qPrintable(QStringLiteral("%1: plot %2 is in %3 declared plot groups").arg(where, plot_name).arg(holders)));
        QVERIFY2(!spec.title.empty(), qPrintable(where + ": plot " + plot_name + " has no title (its tab would show "
                                                                             "the file stem)"));
        QCustomPlot plot;
        plot.resize(800, 500);
        if (!fillPlot(plot, results, spec)) continue;  // a plot of a table this run did not make
        for (const std::string& text : plotTexts(plot)) check(text, "plot " + plot_name);
        const Table* table = results.findTable(spec.table);
        std::vector<std::string> columns = spec.y;
        columns.push_back(spec.x);
        for (const std::string& name : columns) {
          const Column* c = table->find(name);
          const std::string key = b.scenario.scene + ": " + spec.table + "." + name;
          if (c->label.empty() && seen_fallbacks.insert(key).second) fallbacks << QString::fromStdString(key);
          declared += !c->label.empty();
        }
      }
      // Warnings (the scene's plausibility checks among them) as the run log and the results dock show them.
      for (const std::string& w : results.warnings)
        check(withFieldNames(w, scene.schema).toStdString(), QStringLiteral("warning"));
      for (const Scalar& s : results.scalars) {
        check(displayLabel(s), QStringLiteral("scalar"));
        const std::string key = b.scenario.scene + ": scalar " + s.name;
        if (s.label.empty() && seen_fallbacks.insert(key).second) fallbacks << QString::fromStdString(key);
        declared += !s.label.empty();
      }
    }
    // Every name a scene's plot groups declare is a plot of one of its built-in scenarios (no name left behind);
    // the sanitizers' shortened examples do not run every scenario.
    if (!test::kSanitizedBuild)
      for (const auto& [scene, names] : unused_group_names)
        for (const std::string& name : names) QFAIL(qPrintable(QString::fromStdString(scene + ": plot group name " + name + " matches no plot")));
    qInfo("%d texts scanned; %d plotted columns and scalars with a declared label; %lld fall back to their name:",
          texts, declared, static_cast<long long>(fallbacks.size()));
    for (const QString& f : fallbacks) qInfo("  fallback %s", qPrintable(f));
    QVERIFY2(offenders.isEmpty(), qPrintable(QStringLiteral("internal names shown to people:\n") + offenders.join('\n')));
    // Every plotted column and every scalar of the built-in scenarios declares its label where it is made.
    QVERIFY2(fallbacks.isEmpty(), qPrintable(QStringLiteral("no declared label:\n") + fallbacks.join('\n')));
  }
};

QTEST_MAIN(LabelsTest)
#include "test_labels.moc"
