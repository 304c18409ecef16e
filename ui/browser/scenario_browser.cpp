#include "browser/scenario_browser.hpp"

#include <QFileInfo>
#include <QHeaderView>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "scene_library.hpp"

namespace maris::ui {

namespace {

enum ItemRole { kKindRole = Qt::UserRole, kKeyRole };
enum ItemKind { kExample = 1, kFile = 2 };

}  // namespace

ScenarioBrowser::ScenarioBrowser(std::shared_ptr<const SceneLibrary> library, QWidget* parent)
    : QWidget(parent), library_(std::move(library)), tree_(new QTreeWidget(this)) {
  tree_->setHeaderHidden(true);
  tree_->setColumnCount(1);
  tree_->setObjectName(QStringLiteral("scenarioTree"));
  for (const auto& scene : library_->scenes) {
    auto* group = new QTreeWidgetItem(tree_, {QString::fromStdString(scene.title)});
    group->setToolTip(0, QString::fromStdString(scene.description));
    group->setFlags(Qt::ItemIsEnabled);
    for (const auto& example : library_->examples) {
      if (example.scenario.scene != scene.name) continue;
      auto* item = new QTreeWidgetItem(group, {QString::fromStdString(example.scenario.name)});
      item->setData(0, kKindRole, kExample);
      item->setData(0, kKeyRole, QString::fromStdString(example.id));
      item->setToolTip(0, QStringLiteral("<b>%1</b><br>%2")
                              .arg(QString::fromStdString(example.id),
                                   QString::fromStdString(example.scenario.description).toHtmlEscaped()));
    }
    group->setExpanded(true);
  }
  recent_ = new QTreeWidgetItem(tree_, {tr("Recent files")});
  recent_->setFlags(Qt::ItemIsEnabled);
  recent_->setExpanded(true);

  auto* open = new QPushButton(tr("Open file…"), this);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(tree_, 1);
  layout->addWidget(open);
  connect(open, &QPushButton::clicked, this, &ScenarioBrowser::openFileRequested);
  connect(tree_, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item, int) { onActivated(item); });
}

void ScenarioBrowser::setRecentFiles(const QStringList& files) {
  qDeleteAll(recent_->takeChildren());
  for (const QString& file : files) {
    auto* item = new QTreeWidgetItem(recent_, {QFileInfo(file).fileName()});
    item->setData(0, kKindRole, kFile);
    item->setData(0, kKeyRole, file);
    item->setToolTip(0, file);
  }
  recent_->setHidden(files.isEmpty());
  refreshBold();
}

void ScenarioBrowser::setCurrent(const QString& example_id, const QString& file) {
  current_example_ = example_id;
  current_file_ = file;
  refreshBold();
}

void ScenarioBrowser::refreshBold() {
  for (int g = 0; g < tree_->topLevelItemCount(); ++g) {
    QTreeWidgetItem* group = tree_->topLevelItem(g);
    for (int i = 0; i < group->childCount(); ++i) {
      QTreeWidgetItem* item = group->child(i);
      const QString key = item->data(0, kKeyRole).toString();
      const bool current = item->data(0, kKindRole).toInt() == kExample ? key == current_example_ && current_file_.isEmpty()
                                                                         : key == current_file_;
      QFont font = item->font(0);
      font.setBold(current);
      item->setFont(0, font);
      // The open scenario is selected and scrolled into view (it may be far down the list).
      if (current) {
        tree_->setCurrentItem(item);
        tree_->scrollToItem(item, QAbstractItemView::PositionAtCenter);
      }
    }
  }
}

void ScenarioBrowser::onActivated(QTreeWidgetItem* item) {
  const QString key = item->data(0, kKeyRole).toString();
  switch (item->data(0, kKindRole).toInt()) {
    case kExample: emit exampleActivated(key); break;
    case kFile: emit fileActivated(key); break;
    default: break;
  }
}

}  // namespace maris::ui
