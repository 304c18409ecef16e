// A layout that places its items left to right and starts a new row where the next item would pass the right
// edge, so a row of buttons stays whole in a narrow panel (a 1366-pixel screen) instead of hiding its last
// buttons behind an overflow arrow, and stays one row where there is room. Its minimum width is its widest item;
// its height follows its width (heightForWidth), so the layouts above it make room for the extra rows.
#pragma once

#include <QLayout>
#include <QList>

namespace maris::ui {

class FlowLayout : public QLayout {
 public:
  explicit FlowLayout(QWidget* parent = nullptr, int spacing = 4);
  ~FlowLayout() override;

  void addItem(QLayoutItem* item) override;
  int count() const override { return static_cast<int>(items_.size()); }
  QLayoutItem* itemAt(int index) const override;
  QLayoutItem* takeAt(int index) override;

  Qt::Orientations expandingDirections() const override { return {}; }
  bool hasHeightForWidth() const override { return true; }
  int heightForWidth(int width) const override;
  QSize minimumSize() const override;
  QSize sizeHint() const override;
  void setGeometry(const QRect& rect) override;

 private:
  // Places the items in `rect` (only measures when `apply` is false); returns the height used.
  int arrange(const QRect& rect, bool apply) const;

  QList<QLayoutItem*> items_;
};

}  // namespace maris::ui
