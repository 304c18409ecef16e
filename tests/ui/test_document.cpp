// The scenario document, its one generic undo command and the schema-built parameter editor,
// without a main window (offscreen platform). Also opens every built-in scenario of the engine.
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QTableWidget>
#include <QToolButton>
#include <QUndoStack>
#include <QtTest>

#include "document/scenario_document.hpp"
#include "editor/field_text.hpp"
#include "editor/parameter_editor.hpp"
#include "editor/table_editor.hpp"
#include "scene_library.hpp"
#include "test_scene.hpp"
#include "ui_test_support.hpp"

using namespace maris;
using namespace maris::ui;

class DocumentTest : public QObject {
  Q_OBJECT

  std::shared_ptr<const SceneLibrary> library_ = test::rodLibrary();

  void openDefault(ScenarioDocument& doc) {
    const auto& example = library_->examples.front();
    doc.reset(library_->findScene(example.scenario.scene), example.scenario);
  }

 private slots:
  void initTestCase() { test::isolateSettings(); }

  void fieldTextParsesWhatUsersType_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("json");
    QTest::newRow("real") << "1.5e3" << int(ParamKind::Real) << "1500.0";
    QTest::newRow("real with spaces") << " 2 " << int(ParamKind::Real) << "2.0";
    QTest::newRow("word in a number field") << "abc" << int(ParamKind::Real) << "\"abc\"";
    QTest::newRow("integer") << "42" << int(ParamKind::Integer) << "42";
    QTest::newRow("fraction in an integer field") << "4.5" << int(ParamKind::Integer) << "4.5";
    QTest::newRow("boolean") << "yes" << int(ParamKind::Boolean) << "true";
    QTest::newRow("list") << "1, 2.5,3" << int(ParamKind::RealList) << "[1.0,2.5,3.0]";
    QTest::newRow("empty list") << "" << int(ParamKind::RealList) << "[]";
  }
  void fieldTextParsesWhatUsersType() {
    QFETCH(QString, text);
    QFETCH(int, kind);
    QFETCH(QString, json);
    QCOMPARE(QString::fromStdString(parseFieldText(text, static_cast<ParamKind>(kind)).dump()), json);
  }

  // Very large and small reals show in scientific notation (a 2.07e11 Pa modulus fits its field)
  // and read back to the same double; ordinary ones keep their JSON form.
  void realsShowCompactlyAndReadBackExactly_data() {
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("shown");
    QTest::newRow("Young's modulus") << 2.07e11 << "2.07e+11";
    QTest::newRow("small") << 3e-5 << "3e-05";
    QTest::newRow("ordinary") << 100.0 << "100.0";
    QTest::newRow("fraction") << 0.45 << "0.45";
    QTest::newRow("negative large") << -1.234567890123e7 << "-1.234567890123e+07";
  }
  void realsShowCompactlyAndReadBackExactly() {
    QFETCH(double, value);
    QFETCH(QString, shown);
    QCOMPARE(fieldText(Json(value), ParamKind::Real), shown);
    QCOMPARE(parseFieldText(shown, ParamKind::Real).get<double>(), value);
  }

  void editIsUndoneAndRedone() {
    ScenarioDocument doc;
    openDefault(doc);
    QVERIFY(!doc.isModified());
    doc.edit("geometry.length", 200.0);
    QVERIFY(doc.isModified());
    QCOMPARE(doc.undoStack()->undoText(), QStringLiteral("Set Length L to 200.0 m"));
    doc.undoStack()->undo();
    QCOMPARE(doc.value("geometry.length").get<double>(), 100.0);
    QVERIFY(!doc.isModified());
    doc.undoStack()->redo();
    QCOMPARE(doc.value("geometry.length").get<double>(), 200.0);
  }

  void quickEditsOfOneFieldMergeIntoOneStep() {
    ScenarioDocument doc;
    openDefault(doc);
    doc.edit("geometry.length", 110.0);
    doc.edit("geometry.length", 120.0);
    doc.edit("geometry.radius", 1.0);
    QCOMPARE(doc.undoStack()->count(), 2);
    doc.undoStack()->undo();
    doc.undoStack()->undo();
    QCOMPARE(doc.value("geometry.length").get<double>(), 100.0);
    QCOMPARE(doc.value("geometry.radius").get<double>(), 0.5);
  }

  void invalidValuesAreReportedAtTheirPath() {
    ScenarioDocument doc;
    openDefault(doc);
    doc.edit("geometry.length", -1.0);
    QVERIFY(!doc.isValid());
    QVERIFY(doc.errorText("geometry.length").contains(QStringLiteral("(0, 1000]")));
    QVERIFY(doc.errorText("geometry.radius").isEmpty());
    doc.edit("geometry.length", 100.0);
    doc.edit("sections", Json::parse(R"([{"length": 50.0, "outer_diameter": -2.0}])"));
    QVERIFY(doc.errorText("sections").contains(QStringLiteral("outer_diameter")));
  }

  void editorTypingCommitsAnUndoableEdit() {
    ScenarioDocument doc;
    ParameterEditor editor(&doc);
    openDefault(doc);
    auto* length = qobject_cast<QLineEdit*>(editor.fieldWidget("geometry.length"));
    QVERIFY(length);
    length->selectAll();
    QTest::keyClicks(length, QStringLiteral("250"));
    QTest::keyClick(length, Qt::Key_Return);
    QCOMPARE(doc.value("geometry.length").get<double>(), 250.0);
    QVERIFY(editor.resetButton("geometry.length")->isEnabled());
    doc.undoStack()->undo();
    QCOMPARE(length->text(), QStringLiteral("100.0"));
    QVERIFY(!editor.resetButton("geometry.length")->isEnabled());
    doc.undoStack()->redo();
    QCOMPARE(length->text(), QStringLiteral("250.0"));
  }

  void editorShowsUnitsTooltipsAndErrors() {
    ScenarioDocument doc;
    ParameterEditor editor(&doc);
    openDefault(doc);
    QWidget* length = editor.fieldWidget("geometry.length");
    QVERIFY(length->toolTip().contains(QStringLiteral("Rod length")));
    QVERIFY(length->toolTip().contains(QStringLiteral("(0, 1000]")));
    QVERIFY(length->toolTip().contains(QStringLiteral("Default: 100.0")));
    doc.edit("geometry.length", 5000.0);
    QVERIFY(!editor.errorLabel("geometry.length")->isHidden());
    QVERIFY(editor.errorLabel("geometry.length")->text().contains(QStringLiteral("must be")));
    QVERIFY(!editor.problemsLabel()->isHidden());
    editor.resetButton("geometry.length")->click();
    QVERIFY(editor.errorLabel("geometry.length")->isHidden());
    QVERIFY(doc.isValid());
  }

  void choiceAndTableEditsGoThroughTheUndoStack() {
    ScenarioDocument doc;
    ParameterEditor editor(&doc);
    openDefault(doc);
    auto* method = qobject_cast<QComboBox*>(editor.fieldWidget("run.method"));
    QVERIFY(method);
    method->setCurrentIndex(1);
    emit method->activated(1);
    QCOMPARE(doc.value("run.method").get<std::string>(), std::string("absolute"));
    auto* table = qobject_cast<TableEditor*>(editor.fieldWidget("sections"));
    QVERIFY(table);
    QCOMPARE(table->grid()->rowCount(), 2);
    table->grid()->item(1, 1)->setText(QStringLiteral("0.8"));
    QCOMPARE(doc.value("sections")[1]["outer_diameter"].get<double>(), 0.8);
    table->grid()->item(0, 1)->setText(QStringLiteral("-1"));
    QVERIFY(!doc.isValid());
    QCOMPARE(table->grid()->item(0, 1)->toolTip().contains(QStringLiteral("must be")), true);
    const int steps = doc.undoStack()->count();
    doc.undoStack()->undo();
    QVERIFY(doc.isValid());
    QCOMPARE(doc.undoStack()->count(), steps);
  }

  // Every built-in scenario of the engine opens in the editor, valid, with a widget per field.
  void opensEveryBuiltinScenario_data() {
    QTest::addColumn<QString>("id");
    const auto engine = SceneLibrary::fromEngine();
    for (const auto& example : engine->examples) QTest::newRow(example.id.c_str()) << QString::fromStdString(example.id);
    if (engine->examples.empty()) QTest::newRow("(no scenes compiled in yet)") << QString();
  }
  void opensEveryBuiltinScenario() {
    QFETCH(QString, id);
    if (id.isEmpty()) QSKIP("the engine has no built-in scenarios in this build");
    const auto engine = SceneLibrary::fromEngine();
    const BuiltinScenario* example = engine->findExample(id.toStdString());
    QVERIFY(example);
    const SceneDefinition* scene = engine->findScene(example->scenario.scene);
    QVERIFY(scene);
    ScenarioDocument doc;
    ParameterEditor editor(&doc);
    doc.reset(scene, example->scenario);
    QVERIFY2(doc.isValid(), doc.errors().empty() ? "" : doc.errors().front().str().c_str());
    for (const auto& spec : scene->schema.fields) QVERIFY2(editor.fieldWidget(spec.path), spec.path.c_str());
  }
};

QTEST_MAIN(DocumentTest)
#include "test_document.moc"
