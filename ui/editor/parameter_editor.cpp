#include "editor/parameter_editor.hpp"

#include <algorithm>
#include <vector>

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QScrollArea>
#include <QSplitter>
#include <QSignalBlocker>
#include <QStyle>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

#include "counted.hpp"
#include "document/scenario_document.hpp"
#include "editor/field_text.hpp"
#include "themed_icon.hpp"
#include "editor/table_editor.hpp"
#include "plots/display_units.hpp"
#include "study/study.hpp"

namespace maris::ui {

namespace {

const char* kInvalidStyle = "border: 1px solid #d62728; background: rgba(214, 39, 40, 40);";
const char* kDoubtfulStyle = "border: 1px solid #c77c02; background: rgba(255, 170, 0, 40);";
const char* kErrorTextStyle = "color: #d62728;";
const char* kWarningTextStyle = "color: #a86400;";

}  // namespace

ParameterEditor::ParameterEditor(ScenarioDocument* document, QWidget* parent)
    : QWidget(parent), document_(document), title_(new QLabel(this)), description_(new QLabel(this)),
      problems_(new QLabel(this)) {
  title_->setObjectName(QStringLiteral("scenarioTitle"));
  title_->setWordWrap(true);
  QFont bold = title_->font();
  bold.setBold(true);
  bold.setPointSizeF(bold.pointSizeF() * 1.15);
  title_->setFont(bold);
  description_->setWordWrap(true);
  description_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  problems_->setWordWrap(true);
  problems_->setStyleSheet(QString::fromLatin1(kErrorTextStyle));

  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  fields_host_ = new QWidget(scroll);
  fields_layout_ = new QVBoxLayout(fields_host_);
  scroll->setWidget(fields_host_);

  // The title and description in a pane of their own above the fields, a quarter of the height to begin with
  // (drag the handle for more): in a narrow column (a 1366 px screen) the wrapped description alone would
  // otherwise take most of the dock's height and leave room for one field.
  auto* header = new QScrollArea(this);
  header->setWidgetResizable(true);
  header->setFrameShape(QFrame::NoFrame);
  header->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // the labels wrap to its width
  auto* header_content = new QWidget(header);
  auto* header_layout = new QVBoxLayout(header_content);
  header_layout->setContentsMargins(0, 0, 0, 0);
  header_layout->addWidget(title_);
  header_layout->addWidget(description_);
  header_layout->addStretch(1);
  header->setWidget(header_content);
  auto* split = new QSplitter(Qt::Vertical, this);
  split->setChildrenCollapsible(false);
  split->addWidget(header);
  split->addWidget(scroll);
  split->setStretchFactor(0, 1);
  split->setStretchFactor(1, 3);
  split->setSizes({1, 3});  // proportions: the splitter scales them to its height

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(problems_);
  layout->addWidget(split, 1);

  connect(document_, &ScenarioDocument::scenarioReset, this, &ParameterEditor::rebuild);
  connect(document_, &ScenarioDocument::valueChanged, this,
          [this](const QString& path) { refreshValue(path.toStdString()); });
  connect(document_, &ScenarioDocument::errorsChanged, this, &ParameterEditor::refreshErrors);
  rebuild();
}

QWidget* ParameterEditor::fieldWidget(const std::string& path) const {
  const auto it = rows_.find(path);
  return it == rows_.end() ? nullptr : it->second.editor;
}

QLabel* ParameterEditor::errorLabel(const std::string& path) const {
  const auto it = rows_.find(path);
  return it == rows_.end() ? nullptr : it->second.error;
}

QToolButton* ParameterEditor::resetButton(const std::string& path) const {
  const auto it = rows_.find(path);
  return it == rows_.end() ? nullptr : it->second.reset;
}

QMenu* ParameterEditor::fieldMenu(const std::string& path, QWidget* parent) {
  const auto it = rows_.find(path);
  if (it == rows_.end()) return nullptr;
  const Row& row = it->second;
  auto* line = qobject_cast<QLineEdit*>(row.editor);
  QMenu* menu = line ? line->createStandardContextMenu() : new QMenu;
  menu->setParent(parent, Qt::Popup);
  if (row.spec->kind == ParamKind::Real || row.spec->kind == ParamKind::Integer) {
    if (!menu->isEmpty()) menu->addSeparator();
    QAction* sweep = menu->addAction(tr("Sweep this parameter…"));
    sweep->setObjectName(QStringLiteral("sweepAction"));
    const QString p = QString::fromStdString(path);
    connect(sweep, &QAction::triggered, this, [this, p] { emit sweepRequested(p); });
  }
  return menu;
}

void ParameterEditor::rebuild() {
  // Old editors must not commit their text (focus-out) into the new scenario while they go.
  for (auto& [path, row] : rows_) row.editor->blockSignals(true);
  rows_.clear();
  while (QLayoutItem* item = fields_layout_->takeAt(0)) {
    delete item->widget();
    delete item;
  }
  const SceneDefinition* scene = document_->scene();
  if (!scene) {
    title_->setText(tr("No scenario open"));
    description_->clear();
    problems_->clear();
    return;
  }
  const Scenario& scenario = document_->scenario();
  title_->setText(QStringLiteral("%1 — %2").arg(QString::fromStdString(scenario.name),
                                               QString::fromStdString(scene->title)));
  description_->setText(QString::fromStdString(scenario.description.empty() ? scene->description
                                                                            : scenario.description));
  // Groups in order of first appearance in the schema.
  std::map<std::string, QGridLayout*> groups;
  std::vector<QLabel*> labels, units;
  for (const ParamSpec& spec : scene->schema.fields) {
    QGridLayout*& grid = groups[spec.group()];
    if (!grid) {
      auto* box = new QGroupBox(groupTitle(spec.group()), fields_host_);
      grid = new QGridLayout(box);
      grid->setColumnStretch(1, 1);
      fields_layout_->addWidget(box);
    }
    Row row;
    row.spec = &spec;
    row.editor = makeEditor(spec);
    row.editor->setObjectName(QString::fromStdString("field:" + spec.path));
    row.editor->setToolTip(fieldTooltip(spec));
    auto* label = new QLabel(fieldLabel(spec), fields_host_);
    label->setToolTip(fieldTooltip(spec));
    label->setBuddy(row.editor);
    auto* unit = new QLabel(unitText(spec.unit), fields_host_);
    if (spec.kind != ParamKind::Table) labels.push_back(label);
    units.push_back(unit);
    row.reset = new QToolButton(fields_host_);
    row.reset->setIcon(themedIcon(QStyle::SP_BrowserReload));
    row.reset->setToolTip(tr("Reset to default (%1)").arg(fieldText(spec.default_value, spec.kind)));
    row.reset->setAutoRaise(true);
    row.reset->setFocusPolicy(Qt::NoFocus);  // Tab goes from field to field, not through these
    row.error = new QLabel(fields_host_);
    row.error->setWordWrap(true);
    row.error->setStyleSheet(QString::fromLatin1(kErrorTextStyle));
    row.error->hide();
    if (spec.kind == ParamKind::Real || spec.kind == ParamKind::Integer)
      for (QWidget* w : {static_cast<QWidget*>(label), row.editor}) {
        w->setContextMenuPolicy(Qt::CustomContextMenu);
        connect(w, &QWidget::customContextMenuRequested, this, [this, w, path = spec.path](const QPoint& at) {
          QMenu* menu = fieldMenu(path, this);
          menu->setAttribute(Qt::WA_DeleteOnClose);
          menu->popup(w->mapToGlobal(at));
        });
      }
    connect(row.reset, &QToolButton::clicked, this,
            [this, &spec] { document_->edit(spec.path, spec.default_value); });

    const int r = grid->rowCount();
    if (spec.kind == ParamKind::Table) {
      grid->addWidget(label, r, 0, 1, 2);
      grid->addWidget(row.reset, r, 3);
      grid->addWidget(row.editor, r + 1, 0, 1, 4);
      grid->addWidget(row.error, r + 2, 0, 1, 4);
    } else {
      grid->addWidget(label, r, 0);
      grid->addWidget(row.editor, r, 1);
      grid->addWidget(unit, r, 2);
      grid->addWidget(row.reset, r, 3);
      grid->addWidget(row.error, r + 1, 0, 1, 4);
    }
    rows_[spec.path] = row;
    refreshValue(spec.path);
  }
  fields_layout_->addStretch(1);
  // Every group box has its own grid: equal label and unit columns line the editors up across them.
  int label_width = 0, unit_width = 0;
  for (QLabel* l : labels) label_width = std::max(label_width, l->sizeHint().width());
  // A long label wraps onto two lines rather than widening every group past the dock.
  label_width = std::min(label_width, fontMetrics().horizontalAdvance(QStringLiteral("outer diameter of the")));
  for (QLabel* l : labels) l->setWordWrap(true);
  for (QLabel* u : units) unit_width = std::max(unit_width, u->sizeHint().width());
  for (QLabel* l : labels) l->setMinimumWidth(label_width);
  for (QLabel* u : units) u->setMinimumWidth(unit_width);
  refreshErrors();
  updateGeometry();  // the new fields' minimum width
}

QSize ParameterEditor::minimumSizeHint() const {
  const QSize own = QWidget::minimumSizeHint();
  const QMargins m = layout() ? layout()->contentsMargins() : QMargins();
  const int scroll_bar = style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, this);
  const int fields = fields_host_->minimumSizeHint().width() + scroll_bar + m.left() + m.right() + 4;
  return {std::max({own.width(), fields, kMinimumWidth}), own.height()};
}

QWidget* ParameterEditor::makeEditor(const ParamSpec& spec) {
  switch (spec.kind) {
    case ParamKind::Boolean: {
      auto* box = new QCheckBox(fields_host_);
      connect(box, &QCheckBox::toggled, this, [this, &spec](bool on) { document_->edit(spec.path, Json(on)); });
      return box;
    }
    case ParamKind::Choice: {
      auto* combo = new QComboBox(fields_host_);
      // Sized like the number fields, not to its longest choice: a long choice name must not
      // widen every group's editor column past the dock (the popup list still shows it whole).
      combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
      combo->setMinimumContentsLength(12);
      for (const auto& choice : spec.choices) combo->addItem(QString::fromStdString(choice));
      connect(combo, &QComboBox::activated, this,
              [this, &spec, combo](int) { document_->edit(spec.path, Json(combo->currentText().toStdString())); });
      return combo;
    }
    case ParamKind::Table: {
      auto* table = new TableEditor(spec, fields_host_);
      connect(table, &TableEditor::edited, this, [this, &spec](const Json& rows) { document_->edit(spec.path, rows); });
      // A cell is swept by its study path, TABLE[ROW].COLUMN.
      connect(table, &TableEditor::sweepRequested, this, [this, &spec](int r, const QString& column) {
        emit sweepRequested(QString::fromStdString(study::tableCellPath(spec.path, static_cast<std::size_t>(r), column.toStdString())));
      });
      return table;
    }
    case ParamKind::Real:
    case ParamKind::Integer:
    case ParamKind::Text:
    case ParamKind::RealList:
      break;
  }
  auto* line = new QLineEdit(fields_host_);
  line->installEventFilter(this);
  if (spec.kind == ParamKind::RealList) line->setPlaceholderText(tr("comma-separated numbers"));
  line->setMinimumWidth(line->fontMetrics().horizontalAdvance(QStringLiteral("-1.2345e+100")));
  connect(line, &QLineEdit::editingFinished, this, [this, &spec, line] { commitText(spec, line->text()); });
  return line;
}

bool ParameterEditor::eventFilter(QObject* watched, QEvent* event) {
  // A line edit keeps Ctrl+Z / Ctrl+Shift+Z for its own text undo, so the document's undo shortcuts
  // never fire while a field has focus. Here they act on the document: the field claims the keys
  // (ShortcutOverride) and its key press undoes or redoes the document's last change. Undo first
  // drops typing not yet committed (the field shows the document's value again).
  if (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress)
    return QWidget::eventFilter(watched, event);
  auto* key = static_cast<QKeyEvent*>(event);
  const bool undo = key->matches(QKeySequence::Undo);
  const bool redo = key->matches(QKeySequence::Redo);
  if (!undo && !redo) return QWidget::eventFilter(watched, event);
  if (event->type() == QEvent::ShortcutOverride) {
    event->accept();
    return true;
  }
  auto* line = qobject_cast<QLineEdit*>(watched);
  for (const auto& [path, row] : rows_)
    if (undo && row.editor == line && line->text() != fieldText(document_->value(path), row.spec->kind)) {
      refreshValue(path);
      return true;
    }
  if (undo)
    document_->undoStack()->undo();
  else
    document_->undoStack()->redo();
  return true;
}

void ParameterEditor::commitText(const ParamSpec& spec, const QString& text) {
  document_->edit(spec.path, parseFieldText(text, spec.kind));
}

void ParameterEditor::refreshValue(const std::string& path) {
  const auto it = rows_.find(path);
  if (it == rows_.end()) return;
  const Row& row = it->second;
  const Json value = document_->value(path);
  if (auto* line = qobject_cast<QLineEdit*>(row.editor)) {
    const QString text = fieldText(value, row.spec->kind);
    if (line->text() != text) {
      line->setText(text);
      line->setCursorPosition(0);  // long values show their first digits, not their last
    }
  } else if (auto* box = qobject_cast<QCheckBox*>(row.editor)) {
    const QSignalBlocker blocker(box);
    box->setChecked(value.is_boolean() && value.get<bool>());
  } else if (auto* combo = qobject_cast<QComboBox*>(row.editor)) {
    const QSignalBlocker blocker(combo);
    combo->setCurrentText(value.is_string() ? QString::fromStdString(value.get<std::string>()) : QString());
  } else if (auto* table = qobject_cast<TableEditor*>(row.editor)) {
    table->setValue(value);
  }
  row.reset->setEnabled(value != row.spec->default_value);
}

void ParameterEditor::refreshErrors() {
  const auto& errors = document_->errors();
  for (auto& [path, row] : rows_) {
    const QString message = document_->errorText(path);
    // A valid value the model doubts (a plausibility warning) is marked in amber; the run goes ahead.
    const QString doubt = message.isEmpty() ? document_->warningText(path) : QString();
    row.error->setText(message.isEmpty() ? doubt : message);
    row.error->setStyleSheet(QString::fromLatin1(message.isEmpty() ? kWarningTextStyle : kErrorTextStyle));
    row.error->setVisible(!message.isEmpty() || !doubt.isEmpty());
    if (auto* table = qobject_cast<TableEditor*>(row.editor))
      table->markErrors(errors, "parameters." + path);
    else
      row.editor->setStyleSheet(!message.isEmpty() ? QString::fromLatin1(kInvalidStyle)
                                : !doubt.isEmpty() ? QString::fromLatin1(kDoubtfulStyle)
                                                   : QString());
  }
  // Problems no field shows (unknown fields, whole-scenario checks) are listed at the top.
  QStringList loose;
  for (const auto& e : errors) {
    bool shown = false;
    for (const auto& [path, row] : rows_) {
      const std::string full = "parameters." + path;
      if (e.path.compare(0, full.size(), full) == 0 &&
          (e.path.size() == full.size() || e.path[full.size()] == '.' || e.path[full.size()] == '['))
        shown = true;
    }
    if (!shown) loose << (document_->scene() ? withFieldNames(e.str(), document_->scene()->schema) : QString::fromStdString(e.str()));
  }
  QString text;
  if (!errors.empty())
    text = errors.size() == 1 ? tr("1 invalid value: Run is disabled until it is fixed.")
                              : tr("%1 invalid values: Run is disabled until they are fixed.").arg(errors.size());
  if (!loose.isEmpty()) text += QStringLiteral("\n") + loose.join('\n');
  const auto& warnings = document_->warnings();
  if (errors.empty() && !warnings.empty())
    text = tr("%1, marked in amber: the scenario runs, but check the values.")
               .arg(counted(static_cast<int>(warnings.size()), tr("plausibility warning"), tr("plausibility warnings")));
  problems_->setText(text);
  problems_->setStyleSheet(QString::fromLatin1(errors.empty() ? kWarningTextStyle : kErrorTextStyle));
  problems_->setVisible(!text.isEmpty());
}

}  // namespace maris::ui
