#include "plots/plot_list.hpp"

#include <algorithm>

#include <QAbstractItemView>
#include <QEvent>
#include <QScreen>
#include <QScrollBar>
#include <QStandardItemModel>
#include <QStyledItemDelegate>

namespace maris::ui {

namespace {

constexpr int kPlotRole = Qt::UserRole + 1;  // the entry's tab index; -1 on a heading

}  // namespace

PlotTabs::PlotTabs(QWidget* parent) : QTabWidget(parent), bar_(new Bar(this)) { setTabBar(bar_); }

int PlotTabs::unelidedTabWidth(int tab) const { return bar_->fullWidth(tab); }

bool tabsFitUnelided(const PlotTabs& tabs, const std::vector<PlotGroup>& groups, int room) {
  auto width = [&](const std::vector<int>& shown) {
    int sum = 0;
    for (int tab : shown) sum += tabs.unelidedTabWidth(tab);
    return sum;
  };
  if (groups.empty()) {
    std::vector<int> all(static_cast<std::size_t>(tabs.count()));
    for (int i = 0; i < tabs.count(); ++i) all[static_cast<std::size_t>(i)] = i;
    return width(all) <= room;
  }
  return std::all_of(groups.begin(), groups.end(), [&](const PlotGroup& g) { return width(g.plots) <= room; });
}

PlotList::PlotList(QWidget* parent) : QComboBox(parent) {
  setObjectName(QStringLiteral("plotList"));
  setToolTip(tr("The plots of this run"));
  // The closed box takes the panel's width, whatever its longest entry; the open list shows every title whole.
  setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  setMinimumContentsLength(16);
  // An item view's delegate: its size hint is the entry's text (in the entry's font) and margins, which the open
  // list is widened to. (The menu-like delegate of some styles sizes an entry from the list's width instead.)
  setItemDelegate(new QStyledItemDelegate(this));
  connect(this, &QComboBox::currentIndexChanged, this, [this](int row) {
    setToolTip(row >= 0 ? itemText(row) : tr("The plots of this run"));
    if (!quiet_ && plotOfRow(row) >= 0) emit plotChosen(plotOfRow(row));
  });
}

void PlotList::setPlots(const QStringList& titles, const std::vector<PlotGroup>& groups) {
  quiet_ = true;
  clear();
  auto* items = qobject_cast<QStandardItemModel*>(model());
  auto addPlot = [&](int tab) {
    addItem(titles.value(tab));
    setItemData(count() - 1, tab, kPlotRole);
    setItemData(count() - 1, titles.value(tab), Qt::ToolTipRole);
  };
  if (groups.empty()) {
    for (int tab = 0; tab < titles.size(); ++tab) addPlot(tab);
  } else {
    for (const PlotGroup& g : groups) {
      addItem(g.title);
      setItemData(count() - 1, -1, kPlotRole);
      if (QStandardItem* heading = items ? items->item(count() - 1) : nullptr) {
        heading->setFlags(heading->flags() & ~(Qt::ItemIsSelectable | Qt::ItemIsEnabled));
        QFont bold = font();
        bold.setBold(true);
        heading->setFont(bold);
      }
      colourHeading(count() - 1);
      for (int tab : g.plots) addPlot(tab);
    }
  }
  // Every entry in view at once: 14 plots and 5 headings take ~450 pixels, within a 768-pixel screen.
  setMaxVisibleItems(std::max(10, count()));
  quiet_ = false;
}

void PlotList::colourHeading(int row) {
  // In the text's own colour, not the faint one of a disabled entry: a heading cannot be chosen but is read.
  setItemData(row, view()->palette().brush(QPalette::Active, QPalette::Text), Qt::ForegroundRole);
}

void PlotList::changeEvent(QEvent* event) {
  QComboBox::changeEvent(event);
  if (event->type() == QEvent::PaletteChange)  // a theme chosen in View ▸ Theme
    for (int row = 0; row < count(); ++row)
      if (isHeading(row)) colourHeading(row);
}

void PlotList::setCurrentPlot(int tab) {
  const int row = rowOfPlot(tab);
  if (row < 0 || row == currentIndex()) return;
  quiet_ = true;
  setCurrentIndex(row);
  quiet_ = false;
}

int PlotList::plotOfRow(int row) const {
  if (row < 0 || row >= count()) return -1;
  const QVariant tab = itemData(row, kPlotRole);
  return tab.isValid() ? tab.toInt() : -1;
}

int PlotList::rowOfPlot(int tab) const {
  for (int row = 0; row < count(); ++row)
    if (plotOfRow(row) == tab) return row;
  return -1;
}

void PlotList::showPopup() {
  QComboBox::showPopup();
  // The open list is as wide as its longest title (QComboBox makes it as wide as the closed box), even where that
  // is wider than the panel; it stays on the screen.
  QAbstractItemView* list = view();
  QWidget* popup = list->window();
  const int scroll_bar = list->verticalScrollBar()->isVisible() ? list->verticalScrollBar()->width() : 0;
  int widest = 0;
  for (int row = 0; row < count(); ++row) widest = std::max(widest, list->sizeHintForIndex(model()->index(row, 0)).width());
  const int missing = widest + scroll_bar - list->viewport()->width();
  if (missing <= 0) return;
  QRect frame = popup->geometry();
  frame.setWidth(frame.width() + missing);
  if (const QScreen* screen = popup->screen()) {
    const QRect room = screen->availableGeometry();
    if (frame.right() > room.right()) frame.moveRight(room.right());
    if (frame.left() < room.left()) frame.moveLeft(room.left());
  }
  popup->setGeometry(frame);
}

}  // namespace maris::ui
