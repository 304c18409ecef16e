// The GUI opening hostile files (the fuzz campaign's classes: deep nesting, number overflow, duplicate
// keys, over-long text, bad bytes, files that are not regular): every one is refused with a message
// naming the file and the problem, and the document that was open stays open, unchanged.
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

#include <sys/stat.h>
#include <unistd.h>

#include "document/scenario_document.hpp"
#include "main_window.hpp"
#include "test_scene.hpp"
#include "ui_test_support.hpp"

using namespace maris;
using namespace maris::ui;

class BadFilesTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() { test::isolateSettings(); }

  void badFilesAreRefusedAndThePreviousDocumentKept() {
    MainWindow window(test::rodLibrary());
    window.setUnsavedPrompt([] { return QMessageBox::Discard; });
    window.resize(1200, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // A good file first: the document every refusal below must leave in place.
    Scenario good = test::rodLibrary()->examples.front().scenario;
    good.parameters["geometry"]["length"] = 123.0;
    const QString good_file = dir.filePath(QStringLiteral("good.json"));
    saveScenarioFile(good, good_file.toStdString());
    QVERIFY(window.openFile(good_file));

    const std::string text = scenarioToText(good);
    auto spliced = [&](const std::string& raw) {  // `raw` as the first member of "parameters"
      std::string t = text;
      return t.insert(t.find("\"parameters\": {") + 15, raw);
    };
    auto write = [&](const char* name, const std::string& content) {
      std::ofstream(dir.filePath(QString::fromLatin1(name)).toStdString(), std::ios::binary) << content;
      return dir.filePath(QString::fromLatin1(name));
    };
    const QString fifo = dir.filePath(QStringLiteral("fifo.json")), loop = dir.filePath(QStringLiteral("loop.json"));
    QCOMPARE(::mkfifo(fifo.toLocal8Bit().constData(), 0600), 0);
    QCOMPARE(::symlink("loop.json", loop.toLocal8Bit().constData()), 0);
    const std::vector<std::pair<QString, QString>> cases = {
        {write("deep.json", spliced("\"d\": " + std::string(60000, '[') + std::string(60000, ']') + ",")),
         QStringLiteral("nested deeper than 64 levels")},
        {write("overflow.json", spliced("\"x\": 1e400,")), QStringLiteral("parameters.x = 1e400")},
        {write("duplicate.json", spliced("\"geometry\": {},")), QStringLiteral("parameters.geometry: duplicate key")},
        {write("long.json", spliced("\"s\": \"" + std::string(200000, 's') + "\",")),
         QStringLiteral("text of 200000 characters")},
        {write("bytes.json", spliced("\"b\": \"\xff\xfe\",")), QStringLiteral("is not valid JSON")},
        {fifo, QStringLiteral("not a regular file")},
        {QStringLiteral("/dev/zero"), QStringLiteral("not a regular file")},
        {dir.path(), QStringLiteral("is a folder")},
        {loop, QStringLiteral("loop of symbolic links")},
    };
    for (const auto& [file, fragment] : cases) {
      QVERIFY2(!window.openFile(file), qPrintable(file));
      QVERIFY2(window.lastError().contains(file), qPrintable(window.lastError()));
      QVERIFY2(window.lastError().contains(fragment), qPrintable(window.lastError()));
      QVERIFY2(window.lastError().size() < 2000, qPrintable(file));
      QCOMPARE(window.document()->filePath(), QFileInfo(good_file).absoluteFilePath());
      QCOMPARE(window.document()->value("geometry.length").get<double>(), 123.0);
    }
  }
};

QTEST_MAIN(BadFilesTest)
#include "test_bad_files.moc"
