// The scenario browser dock: built-in examples grouped by scene (from the library, no scene named
// here), the recently opened files, and an "Open file…" button. Activating an item (double click
// or Enter) asks the main window to open it; the open scenario is shown in bold.
#pragma once

#include <memory>

#include <QStringList>
#include <QWidget>

class QTreeWidget;
class QTreeWidgetItem;

namespace maris::ui {

struct SceneLibrary;

class ScenarioBrowser : public QWidget {
  Q_OBJECT
 public:
  ScenarioBrowser(std::shared_ptr<const SceneLibrary> library, QWidget* parent = nullptr);

  void setRecentFiles(const QStringList& files);
  // Marks the open scenario: a built-in id or a file path (empty: none).
  void setCurrent(const QString& example_id, const QString& file);
  QTreeWidget* tree() const { return tree_; }

 signals:
  void exampleActivated(const QString& id);
  void fileActivated(const QString& path);
  void openFileRequested();

 private:
  void onActivated(QTreeWidgetItem* item);
  void refreshBold();

  std::shared_ptr<const SceneLibrary> library_;
  QTreeWidget* tree_;
  QTreeWidgetItem* recent_ = nullptr;
  QString current_example_;
  QString current_file_;
};

}  // namespace maris::ui
