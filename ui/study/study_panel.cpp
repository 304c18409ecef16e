#include "study/study_panel.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <thread>

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include "core/errors.hpp"
#include "core/run_reader.hpp"
#include "counted.hpp"
#include "document/scenario_document.hpp"
#include "scene_library.hpp"
#include "start_folder.hpp"
#include "plots/study_plot.hpp"
#include "study/study_plot_view.hpp"
#include "study/study_runner.hpp"
#include "study/add_parameter_dialog.hpp"
#include "study/study.hpp"
#include "study/study_folder.hpp"
#include "study/study_cell_text.hpp"
#include "plots/display_units.hpp"

namespace maris::ui {

namespace {

enum Column { kParameter, kFrom, kTo, kValues, kSpacing, kColumnCount };


// A file dialog's folder, remembered per purpose.
QString askFile(QWidget* parent, bool save, const QString& title, const QString& key, const QString& name,
                const QString& filter) {
  const QString last = QSettings().value(QStringLiteral("study/") + key).toString();
  const QString start = startFolder(last) + QLatin1Char('/') + name;
  const QString file = save ? QFileDialog::getSaveFileName(parent, title, start, filter)
                            : QFileDialog::getOpenFileName(parent, title, startFolder(last), filter);
  if (!file.isEmpty()) QSettings().setValue(QStringLiteral("study/") + key, QFileInfo(file).absolutePath());
  return file;
}

}  // namespace

StudyPanel::StudyPanel(ScenarioDocument* document, std::shared_ptr<const SceneLibrary> library, QWidget* parent)
    : QWidget(parent), document_(document), library_(std::move(library)), runner_(new StudyRunner(this)),
      base_(new QLabel(this)), table_(new QTableWidget(0, kColumnCount, this)),
      add_(new QPushButton(tr("Add parameter…"), this)), remove_(new QPushButton(tr("Remove"), this)),
      run_(new QPushButton(tr("Run study"), this)), cancel_(new QPushButton(tr("Cancel"), this)),
      threads_box_(new QSpinBox(this)), summary_(new QLabel(this)), weighted_box_(new QWidget(this)),
      weighted_heading_(new QLabel(weighted_box_)), weighted_table_(new QTableWidget(0, 3, weighted_box_)),
      plot_view_(new StudyPlotView(this)),
      refresh_timer_(new QTimer(this)) {
  sweep_prompt_ = [this](const ParamSpec& spec, const SweepRange& proposed) -> std::optional<std::pair<SweepRange, bool>> {
    SweepDialog dialog(spec, proposed, this);
    dialog.setCaseCheck([this](const SweepRange& range, bool add_only) {
      std::vector<SweepRange> grid = add_only ? grid_ : std::vector<SweepRange>{};
      const auto same = std::find_if(grid.begin(), grid.end(), [&](const SweepRange& r) { return r.path == range.path; });
      if (same != grid.end()) *same = range;
      else grid.push_back(range);
      return gridProblem(std::move(grid));
    });
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    return std::make_pair(dialog.range(), dialog.addOnly());
  };
  parameter_prompt_ = [this](const SceneDefinition& scene, const Json& parameters,
                             const std::vector<std::string>& taken) -> std::string {
    AddParameterDialog dialog(scene, parameters, taken, this);
    return dialog.exec() == QDialog::Accepted ? dialog.path() : std::string();
  };
  weighted_sum_prompt_ = [this](const std::vector<std::string>& columns,
                                const std::vector<std::pair<std::string, std::string>>& known,
                                const WeightedSumChoice& current) -> std::optional<WeightedSumChoice> {
    WeightedSumDialog dialog(columns, known, current, this);
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    return dialog.choice();
  };
  base_->setWordWrap(true);
  summary_->setWordWrap(true);
  table_->setObjectName(QStringLiteral("studyParameters"));
  table_->setHorizontalHeaderLabels({tr("Parameter"), tr("From"), tr("To"), tr("Values"), tr("Spacing")});
  table_->horizontalHeader()->setSectionResizeMode(kParameter, QHeaderView::Stretch);
  for (int c = kFrom; c < kColumnCount; ++c) table_->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
  table_->verticalHeader()->hide();
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setMinimumHeight(table_->horizontalHeader()->sizeHint().height() + 3 * table_->verticalHeader()->defaultSectionSize());
  table_->setMaximumHeight(table_->horizontalHeader()->sizeHint().height() + 6 * table_->verticalHeader()->defaultSectionSize());
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads_box_->setRange(1, std::max(64, hardware));
  threads_box_->setValue(hardware);
  threads_box_->setToolTip(tr("Cases run at once (one worker thread each)"));
  run_->setObjectName(QStringLiteral("runStudy"));
  cancel_->setObjectName(QStringLiteral("cancelStudy"));

  auto* file_menu = new QMenu(this);
  file_menu->addAction(tr("Open study…"), this, [this] {
    const QString f = askFile(this, false, tr("Open study"), QStringLiteral("studyFolder"), {}, tr("Maris study (*.json)"));
    if (!f.isEmpty()) openStudy(f);
  });
  file_menu->addAction(tr("Open study folder…"), this, [this] {
    const QString last = QSettings().value(QStringLiteral("study/studyFolder")).toString();
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Open a study folder (maris-cli study run --out DIR)"),
                                                          startFolder(last));
    if (dir.isEmpty()) return;
    QSettings().setValue(QStringLiteral("study/studyFolder"), QFileInfo(dir).absolutePath());
    openStudyFolder(dir);
  });
  file_menu->addAction(tr("Save study as…"), this, [this] {
    const QString f = askFile(this, true, tr("Save study"), QStringLiteral("studyFolder"), QStringLiteral("study.json"),
                              tr("Maris study (*.json)"));
    if (!f.isEmpty()) saveStudy(f.endsWith(QLatin1String(".json")) ? f : f + ".json");
  });
  file_menu->addSeparator();
  file_menu->addAction(tr("Export study.csv…"), this, [this] {
    const QString f = askFile(this, true, tr("Export study.csv"), QStringLiteral("exportFolder"),
                              QStringLiteral("study.csv"), tr("CSV (*.csv)"));
    if (!f.isEmpty()) exportCsv(f);
  });
  file_menu->addAction(tr("Export plot…"), this, [this] {
    const QString f = askFile(this, true, tr("Export study plot"), QStringLiteral("exportFolder"),
                              QStringLiteral("study_plot.png"), tr("Pictures (*.png *.svg *.pdf)"));
    if (!f.isEmpty()) exportPlot(f);
  });
  file_menu->addSeparator();
  file_menu->addAction(tr("New study from the open scenario"), this, [this] { clearParameters(); });
  file_menu->addAction(tr("New load-case table study (CSV)…"), this, [this] {
    const QString f = askFile(this, false, tr("Load-case table"), QStringLiteral("studyFolder"), {},
                              tr("CSV: one column per parameter path, one row per case (*.csv)"));
    if (!f.isEmpty()) openCaseTable(f);
  });
  file_menu->addAction(tr("New Latin hypercube study…"), this, [this] {
    if (runner_->isRunning() || !document_->scene()) return;
    LatinHypercubeDialog dialog(*document_->scene(), document_->scenario(), this);
    if (dialog.exec() == QDialog::Accepted) defineLatinHypercube(dialog.design());
  });
  weighted_action_ = file_menu->addAction(tr("Weighted sum…"), this, [this] { weightedSumDialog(); });
  weighted_action_->setObjectName(QStringLiteral("weightedSumAction"));
  weighted_action_->setToolTip(tr("A table study: sum each chosen result over the cases, weighted by a column of "
                                  "the table (a scatter diagram's probabilities)"));
  auto* file_button = new QPushButton(tr("Study"), this);
  file_button->setMenu(file_menu);

  auto* definition = new QWidget(this);
  auto* grid = new QGridLayout(definition);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->addWidget(base_, 0, 0, 1, 6);
  grid->addWidget(table_, 1, 0, 1, 6);
  // Two short rows of buttons: the dock fits beside the left column and the central views.
  grid->addWidget(add_, 2, 0);
  grid->addWidget(remove_, 2, 1);
  grid->addWidget(file_button, 2, 2);
  grid->addWidget(run_, 3, 0);
  grid->addWidget(cancel_, 3, 1);
  auto* workers = new QHBoxLayout;
  workers->addWidget(new QLabel(tr("Workers"), this));
  workers->addWidget(threads_box_);
  grid->addLayout(workers, 3, 2);
  grid->addWidget(summary_, 4, 0, 1, 6);
  // The weighted sums of a table study: a short table under the summary (a scatter diagram sums one or two
  // results), the weight column named above it.
  weighted_box_->setObjectName(QStringLiteral("studyWeightedSums"));
  weighted_heading_->setWordWrap(true);
  weighted_heading_->setTextFormat(Qt::RichText);
  weighted_table_->setObjectName(QStringLiteral("studyWeightedSumTable"));
  weighted_table_->setHorizontalHeaderLabels({tr("Result"), tr("Σ weight · result"), tr("Cases without a value")});
  weighted_table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  weighted_table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  weighted_table_->horizontalHeader()->setSectionResizeMode(2, QHeaderView::Stretch);
  weighted_table_->verticalHeader()->hide();
  weighted_table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  auto* weighted_layout = new QVBoxLayout(weighted_box_);
  weighted_layout->setContentsMargins(0, 0, 0, 0);
  weighted_layout->addWidget(weighted_heading_);
  weighted_layout->addWidget(weighted_table_);
  weighted_box_->hide();
  grid->addWidget(weighted_box_, 5, 0, 1, 6);
  grid->setColumnStretch(5, 1);
  auto* split = new QSplitter(Qt::Vertical, this);
  split->addWidget(definition);
  split->addWidget(plot_view_);
  split->setStretchFactor(1, 1);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(split);

  connect(add_, &QPushButton::clicked, this, [this] { addParameterDialog(); });
  connect(remove_, &QPushButton::clicked, this, [this] {
    const int row = table_->currentRow();
    if (row >= 0 && row < static_cast<int>(grid_.size())) removeParameter(grid_[row].path);
  });
  connect(run_, &QPushButton::clicked, this, [this] { startStudy(); });
  connect(cancel_, &QPushButton::clicked, this, &StudyPanel::cancelStudy);
  connect(threads_box_, &QSpinBox::valueChanged, this, [this](int n) { threads_ = n; });
  connect(table_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
    const int row = item->row();
    if (row < 0 || row >= static_cast<int>(grid_.size()) || item->column() == kParameter) return;
    SweepRange& r = grid_[row];
    bool ok = false;
    const double v = item->text().trimmed().toDouble(&ok);
    if (item->column() == kFrom) r.from = ok ? v : std::nan("");
    if (item->column() == kTo) r.to = ok ? v : std::nan("");
    if (item->column() == kValues) r.count = ok ? static_cast<int>(v) : 0;
    rebuildTable();
  });
  connect(runner_, &StudyRunner::caseFinished, this, &StudyPanel::onCaseFinished);
  connect(runner_, &StudyRunner::caseFailed, this, &StudyPanel::onCaseFailed);
  connect(runner_, &StudyRunner::runningChanged, this, &StudyPanel::updateButtons);
  refresh_timer_->setSingleShot(true);
  refresh_timer_->setInterval(250);
  connect(refresh_timer_, &QTimer::timeout, plot_view_, &StudyPlotView::refresh);
  connect(refresh_timer_, &QTimer::timeout, this, &StudyPanel::showWeightedSums);
  connect(runner_, &StudyRunner::finished, this, [this](int succeeded, int failed) {
    refresh_timer_->stop();
    plot_view_->refresh();
    showWeightedSums();
    const QString text = tr("Study finished: %1 of %2 cases succeeded, %3 failed")
                             .arg(succeeded).arg(session_.caseCount()).arg(failed);
    summary_->setText(text);
    emit logged(failed ? 1 : 0, text);
    // The weighted sums in the run log too, as `maris-cli study collect` prints them: a record beside the run's.
    if (from_file_)
      for (const study::WeightedSum& sum : session_.weightedSums()) {
        const QString unit = unitText(sum.unit).isEmpty() ? QString() : QStringLiteral(" ") + unitText(sum.unit);
        emit logged(sum.value ? 0 : 1,
                    sum.value ? tr("Weighted sum of %1 over %2: %3%4 (weights add up to %5)")
                                    .arg(QString::fromStdString(sum.result), QString::fromStdString(session_.weightColumn()),
                                         displayValue(Json(*sum.value)), unit, QString::number(sum.weight_total, 'g', 6))
                              : tr("Weighted sum of %1 over %2: no value, %3 of the weighted cases have none")
                                    .arg(QString::fromStdString(sum.result), QString::fromStdString(session_.weightColumn()))
                                    .arg(sum.missing.size()));
      }
    emit message(text);
    emit studyFinished(succeeded, failed);
  });
  connect(runner_, &StudyRunner::cancelled, this, [this] {
    refresh_timer_->stop();
    session_.markUnfinishedCancelled();
    plot_view_->refresh();
    showWeightedSums();
    const QString text = tr("Study cancelled: the workers stopped %1 ms after the request")
                             .arg(runner_->lastCancelLatency() * 1e3, 0, 'f', 1);
    summary_->setText(text);
    emit logged(0, text);
    emit message(text);
    emit studyCancelled();
  });
  connect(plot_view_, &StudyPlotView::caseClicked, this, &StudyPanel::caseOpened);
  connect(document_, &ScenarioDocument::scenarioReset, this, &StudyPanel::rebuildTable);
  connect(document_, &ScenarioDocument::errorsChanged, this, &StudyPanel::updateButtons);
  plot_view_->setSession(&session_);
  rebuildTable();
}

StudyPanel::~StudyPanel() = default;

std::optional<ParamSpec> StudyPanel::parameterSpec(const std::string& path, QString* why) const {
  const SceneDefinition* scene = from_file_ ? session_.scene() : document_->scene();
  if (!scene) {
    if (why) *why = tr("no scenario is open");
    return std::nullopt;
  }
  std::string reason;
  auto spec = study::findStudyParameter(*scene, baseParameters(), path, &reason);
  if (!spec && why) *why = QString::fromStdString(reason);
  return spec;
}

const Json& StudyPanel::baseParameters() const {
  return from_file_ && session_.isDefined() ? session_.base().parameters : document_->scenario().parameters;
}

bool StudyPanel::sweep(const QString& path) {
  const auto spec = parameterSpec(path.toStdString());
  if (!spec) return false;
  const Json* current = study::findParameterValue(baseParameters(), spec->path);
  const auto answer = sweep_prompt_(*spec, proposedSweep(*spec, current ? *current : Json()));
  if (!answer) return false;
  if (answer->second && fixedDesign()) {
    fail(tr("This %1 study's cases are its design: a parameter cannot be added to it. Start a new study from the "
            "open scenario first (Study ▸ New study from the open scenario).")
             .arg(session_.kindName()));
    return false;
  }
  // A study folder holds its cases, not its base: a sweep run from the editor is then one of the open scenario.
  if (!answer->second && from_file_ && !session_.folder().isEmpty()) from_file_ = false;
  if (!answer->second) grid_.clear();
  addParameter(answer->first);
  return answer->second || startStudy();
}

void StudyPanel::addParameter(const SweepRange& range) {
  const auto it = std::find_if(grid_.begin(), grid_.end(), [&](const SweepRange& r) { return r.path == range.path; });
  if (it != grid_.end())
    *it = range;
  else
    grid_.push_back(range);
  rebuildTable();
}

void StudyPanel::removeParameter(const std::string& path) {
  grid_.erase(std::remove_if(grid_.begin(), grid_.end(), [&](const SweepRange& r) { return r.path == path; }),
              grid_.end());
  rebuildTable();
}

void StudyPanel::clearParameters() {
  grid_.clear();
  from_file_ = false;
  rebuildTable();
  showWeightedSums();
}

void StudyPanel::setThreads(int threads) {
  threads_ = threads;
  if (threads > 0) threads_box_->setValue(threads);
}

bool StudyPanel::isRunning() const { return runner_->isRunning(); }

void StudyPanel::fail(const QString& text) {
  last_error_ = text;
  QString first = text.section(QLatin1Char('\n'), 0, 0);
  if (first.endsWith(QLatin1Char(':'))) first.chop(1);  // what follows is in the run log
  summary_->setText(first);
  emit logged(2, text);
  emit message(first);
}

QString StudyPanel::gridProblem(std::vector<SweepRange> grid) const {
  const SceneDefinition* scene = from_file_ ? session_.scene() : document_->scene();
  if (!scene || (!from_file_ && !document_->isValid())) return {};  // startStudy says what to fix
  for (const SweepRange& r : grid) {
    QString why;
    const auto spec = parameterSpec(r.path, &why);
    if (!spec) return tr("%1: %2").arg(QString::fromStdString(r.path), why);
    if (const QString problem = sweepProblem(*spec, r); !problem.isEmpty())
      return tr("%1: %2").arg(QString::fromStdString(r.path), problem);
  }
  StudySession trial;
  try {
    trial.define(*scene, from_file_ ? session_.base() : document_->scenario(), std::move(grid));
    trial.expand();
  } catch (const InputError& e) {
    QStringList lines = QString::fromStdString(describeErrors(e.errors())).split(QLatin1Char('\n'));
    constexpr int kShownLines = 4;
    if (lines.size() > kShownLines) {
      const auto more = lines.size() - kShownLines;
      lines = lines.mid(0, kShownLines);
      lines << tr("… and %n more", nullptr, static_cast<int>(more));
    }
    return lines.join(QLatin1Char('\n'));
  } catch (const std::exception& e) {
    return QString::fromUtf8(e.what());
  }
  return {};
}

bool StudyPanel::startStudy() {
  if (runner_->isRunning()) return false;
  if (from_file_ && !session_.folder().isEmpty()) {
    fail(tr("This study was opened from its folder %1, where maris-cli runs it: `maris-cli study run STUDY --out %1 "
            "--resume` runs its missing cases.").arg(session_.folder()));
    return false;
  }
  const bool file_study = from_file_ && session_.isDefined();
  if (!file_study) {
    if (!document_->isValid()) {
      fail(tr("Fix the invalid values of the scenario first (marked red in the parameter editor)."));
      return false;
    }
    if (grid_.empty()) {
      fail(tr("Add a parameter to vary first (or right-click a number field: Sweep this parameter…)."));
      return false;
    }
    for (const SweepRange& r : grid_) {
      QString problem;
      if (const auto spec = parameterSpec(r.path, &problem)) problem = sweepProblem(*spec, r);
      if (!problem.isEmpty()) {
        fail(tr("%1: %2").arg(QString::fromStdString(r.path), problem));
        return false;
      }
    }
    session_.define(*document_->scene(), document_->scenario(), grid_);
  } else if (!grid_.empty() && grid_ != session_.grid()) {
    session_.define(*session_.scene(), session_.base(), grid_);
  }
  try {
    session_.expand();
  } catch (const InputError& e) {
    fail(tr("The study has invalid cases (listed in the run log); nothing was run:\n%1")
             .arg(QString::fromStdString(describeErrors(e.errors()))));
    plot_view_->refresh();
    return false;
  } catch (const std::exception& e) {
    fail(tr("The study cannot be built: %1").arg(QString::fromUtf8(e.what())));
    plot_view_->refresh();
    return false;
  }
  plot_view_->refresh();
  showWeightedSums();
  const int threads = threads_ > 0 ? threads_ : threads_box_->value();
  if (!runner_->start(*session_.scene(), session_.caseScenarios(), threads)) return false;
  const QString text = tr("Study started: %1 of %2 on %3")
                           .arg(counted(session_.caseCount(), tr("case"), tr("cases")),
                                QString::fromStdString(session_.base().name),
                                counted(runner_->threadCount(), tr("worker"), tr("workers")));
  summary_->setText(text);
  emit logged(0, text);
  return true;
}

void StudyPanel::cancelStudy() { runner_->cancel(); }

void StudyPanel::onCaseFinished(int index, ResultsPtr results, double wall_time_s) {
  session_.setOutcome(index, {StudySession::Status::Finished, std::move(results), {}, wall_time_s});
  // The plot grows as cases finish: redrawn at most four times a second (a study of small cases
  // finishes hundreds per second), and once more when the study ends.
  if (!refresh_timer_->isActive()) refresh_timer_->start();
}

void StudyPanel::onCaseFailed(int index, const QString& message) {
  session_.setOutcome(index, {StudySession::Status::Failed, nullptr, message, 0.0});
  if (!refresh_timer_->isActive()) refresh_timer_->start();
  emit logged(1, tr("case %1 (%2) failed: %3").arg(session_.caseId(index), session_.caseLabel(index), message));
}

std::optional<RunRecord> StudyPanel::caseRecord(int index, quint64 id, QString* note) const {
  if (note) note->clear();
  if (index < 0 || index >= session_.caseCount()) return std::nullopt;
  const StudySession::CaseOutcome& outcome = session_.outcome(index);
  const QString name = tr("study case %1 (%2)").arg(session_.caseId(index), session_.caseLabel(index));
  if (!outcome.results) {
    if (note)
      *note = outcome.status == StudySession::Status::Failed      ? tr("%1 failed: %2").arg(name, outcome.error)
              : outcome.status == StudySession::Status::Cancelled ? tr("%1 was cancelled: it has no results.").arg(name)
                                                                  : tr("%1 has not run: it has no results yet.").arg(name);
    return std::nullopt;
  }
  RunRecord record;
  record.id = id;
  record.scenario = session_.caseScenario(index);
  record.results = outcome.results;
  record.wall_time_s = outcome.wall_time_s;
  record.started_at = std::chrono::system_clock::now();
  record.label = name;
  if (!session_.folder().isEmpty()) {
    // A study opened from its folder keeps only the cases' scalars in memory: the rest of a case is in its run
    // folder, read when the case is opened.
    const std::filesystem::path dir =
        study::StudyFolder{session_.folder().toStdString()}.caseRun(session_.caseId(index).toStdString());
    try {
      RunFolderContents contents = readRunFolder(dir);
      record.results = std::make_shared<const Results>(std::move(contents.results));
      if (note && !contents.missing.empty()) {
        QStringList missing;
        for (const auto& m : contents.missing) missing << QString::fromStdString(m);
        *note = tr("%1, read from %2; not in the folder: %3")
                    .arg(name, QString::fromStdString(dir.string()), missing.join(QStringLiteral("; ")));
      }
    } catch (const std::exception& e) {
      if (note)
        *note = tr("%1: only its scalars are shown; its run folder cannot be read: %2").arg(name, QString::fromUtf8(e.what()));
    }
  }
  return record;
}

bool StudyPanel::exportCsv(const QString& file) {
  try {
    session_.writeCsv(file);
  } catch (const std::exception& e) {
    fail(tr("Could not write %1: %2").arg(file, QString::fromUtf8(e.what())));
    return false;
  }
  emit message(tr("Wrote %1").arg(file));
  return true;
}

bool StudyPanel::exportPlot(const QString& file) {
  if (!plot_view_->exportTo(file)) {
    fail(plot_view_->hasData() ? tr("Could not write %1 (PNG, SVG or PDF)").arg(file)
                               : tr("No study results to plot: run the study first."));
    return false;
  }
  emit message(tr("Wrote %1").arg(file));
  return true;
}

bool StudyPanel::saveStudy(const QString& file) {
  try {
    if (!from_file_ || !session_.isDefined()) {
      if (document_->isEmpty()) throw std::runtime_error("no scenario is open");
      session_.define(*document_->scene(), document_->scenario(), grid_);
      plot_view_->refresh();
    }
    session_.save(file);
  } catch (const std::exception& e) {
    fail(tr("Could not save the study %1: %2").arg(file, QString::fromUtf8(e.what())));
    return false;
  }
  emit message(tr("Saved %1").arg(file));
  return true;
}

bool StudyPanel::openStudy(const QString& file) {
  if (runner_->isRunning()) return false;
  // A study folder's record: the folder is what the user means (its cases ran there).
  const QFileInfo info(file);
  if (info.fileName() == QLatin1String("study.json") && QFileInfo(info.dir(), QStringLiteral("cases")).isDir())
    return openStudyFolder(info.absolutePath());
  if (!replaceSession(tr("Could not open the study %1").arg(file),
                      [&](StudySession& next) { next.load(file, *library_); }))
    return false;
  emit message(tr("Opened study %1").arg(file));
  return true;
}

bool StudyPanel::openStudyFolder(const QString& dir) {
  if (runner_->isRunning()) return false;
  if (!replaceSession(tr("Could not open the study folder %1").arg(dir),
                      [&](StudySession& next) { next.loadFolder(dir, *library_); }))
    return false;
  int ok = 0, failed = 0;
  for (int i = 0; i < session_.caseCount(); ++i) {
    ok += session_.outcome(i).status == StudySession::Status::Finished;
    failed += session_.outcome(i).status == StudySession::Status::Failed;
  }
  const int missing = session_.caseCount() - ok - failed;
  const QString text = tr("Study folder %1: %2 of %3 cases complete, %4 failed, %5 not run")
                           .arg(dir).arg(ok).arg(session_.caseCount()).arg(failed).arg(missing);
  summary_->setText(text);
  emit logged(failed || missing ? 1 : 0, text);
  emit message(text);
  return true;
}

bool StudyPanel::openCaseTable(const QString& file) {
  if (runner_->isRunning()) return false;
  if (!document_->isValid()) {
    fail(tr("Open a valid scenario first: the load cases vary it."));
    return false;
  }
  // A column that varies no parameter may be the cases' weights (a scatter diagram's probabilities): asked
  // before the table is read, since the engine refuses a column that is neither.
  WeightedSumChoice weighting;
  try {
    const auto columns = StudySession::nonParameterColumns(*document_->scene(), document_->scenario().parameters, file);
    if (!columns.empty()) {
      WeightedSumChoice proposed;
      proposed.column = columns.front();
      if (const auto answer = weighted_sum_prompt_(columns, {}, proposed)) weighting = *answer;
    }
  } catch (const std::exception&) {
    // An unreadable table: defineTable below says why.
  }
  if (!replaceSession(tr("Could not read the case table %1").arg(file), [&](StudySession& next) {
        next.defineTable(*document_->scene(), document_->scenario(), file, weighting.column, weighting.results);
      }))
    return false;
  emit message(tr("Load-case table %1: run the study to run its cases").arg(file));
  return true;
}

bool StudyPanel::defineLatinHypercube(const LatinHypercubeDesign& design) {
  if (runner_->isRunning()) return false;
  if (!document_->isValid()) {
    fail(tr("Open a valid scenario first: the samples vary it."));
    return false;
  }
  if (!replaceSession(tr("The Latin hypercube cannot be built"), [&](StudySession& next) {
        next.defineLatinHypercube(*document_->scene(), document_->scenario(), design);
      }))
    return false;
  emit message(tr("Latin hypercube of %1: run the study to run them").arg(counted(design.samples, tr("case"), tr("cases"))));
  return true;
}

// A bad file or design leaves the current study as it was: the new session is built aside and only then adopted.
bool StudyPanel::replaceSession(const QString& failure, const std::function<void(StudySession&)>& build) {
  StudySession next;
  try {
    build(next);
  } catch (const InputError& e) {
    fail(failure + ":\n" + QString::fromStdString(describeErrors(e.errors())));
    return false;
  } catch (const std::exception& e) {
    fail(failure + ": " + QString::fromUtf8(e.what()));
    return false;
  }
  session_ = std::move(next);
  grid_ = session_.grid();  // empty for a table or a sample
  from_file_ = true;
  plot_view_->refresh();
  rebuildTable();
  showWeightedSums();
  return true;
}

bool StudyPanel::setWeightedSum(const std::string& column, const std::vector<std::string>& results) {
  if (runner_->isRunning()) return false;
  if (from_file_ && !session_.folder().isEmpty()) {
    fail(tr("This study was opened from its folder, whose study.json records the weighted sum it ran with; the dock "
            "shows it and does not change it."));
    return false;
  }
  if (!from_file_ || !session_.isTable()) {
    fail(tr("A weighted sum needs a table study: its weights are a column of the table (Study ▸ New load-case "
            "table study)."));
    return false;
  }
  // A column that varies no parameter is read only as the weights: the engine refuses it otherwise.
  const std::vector<std::string> unused = session_.weightCandidates();
  if (column.empty() && !unused.empty()) {
    QStringList names;
    for (const std::string& c : unused) names << QString::fromStdString(c);
    fail(tr("The weighted sum cannot be cleared: the table's column %1 varies no parameter, and a table study reads "
            "such a column only as its weights. Remove it from the CSV file (and open the table again) to study "
            "the cases without a weighted sum.")
             .arg(names.join(QStringLiteral(", "))));
    return false;
  }
  try {
    session_.setWeightedSum(column, results);
  } catch (const InputError& e) {
    fail(tr("The weighted sum cannot be set:\n%1").arg(QString::fromStdString(describeErrors(e.errors()))));
    return false;
  } catch (const std::exception& e) {
    fail(tr("The weighted sum cannot be set: %1").arg(QString::fromUtf8(e.what())));
    return false;
  }
  showWeightedSums();
  plot_view_->refresh();
  emit message(column.empty() ? tr("The study has no weighted sum now")
                              : tr("Weighted sum over the column %1").arg(QString::fromStdString(column)));
  return true;
}

bool StudyPanel::weightedSumDialog() {
  if (runner_->isRunning() || !from_file_ || !session_.isTable() || !session_.folder().isEmpty()) return false;
  std::vector<std::pair<std::string, std::string>> known;
  for (const std::string& name : session_.resultNames()) known.emplace_back(name, session_.resultLabel(name));
  WeightedSumChoice current;
  current.column = session_.weightColumn();
  current.results = session_.weightedResults();
  const auto answer = weighted_sum_prompt_(session_.weightCandidates(), known, current);
  if (!answer || *answer == current) return false;
  return setWeightedSum(answer->column, answer->results);
}

void StudyPanel::showWeightedSums() {
  const std::string column = from_file_ ? session_.weightColumn() : std::string();
  weighted_box_->setVisible(!column.empty());
  if (column.empty()) {
    weighted_table_->setRowCount(0);
    return;
  }
  const std::vector<study::WeightedSum> sums = session_.weightedSums();  // empty before the cases are expanded
  QString heading = tr("<b>Weighted sums</b> over the cases, each case weighted by the table's column <b>%1</b>")
                        .arg(QString::fromStdString(column).toHtmlEscaped());
  if (!sums.empty())
    heading += tr(" (the weights add up to %1)").arg(QString::number(sums.front().weight_total, 'g', 6));
  weighted_heading_->setText(heading);
  // Why each case without a value has none: still to run (or running), failed, cancelled, or ran without it.
  std::map<std::string, int> index_of;
  for (int i = 0; i < session_.caseCount(); ++i) index_of[session_.caseId(i).toStdString()] = i;
  const std::vector<std::string> names = session_.weightedResults();
  weighted_table_->setRowCount(static_cast<int>(names.size()));
  for (int row = 0; row < static_cast<int>(names.size()); ++row) {
    const std::string& name = names[row];
    const study::WeightedSum* sum = row < static_cast<int>(sums.size()) ? &sums[row] : nullptr;
    const std::string unit = sum ? sum->unit : std::string("-");
    // The result's label from the cases; before a run (no case has it yet) read from its name.
    Scalar named;
    named.name = name;
    const std::string text = session_.resultLabel(name);
    QString label = QString::fromStdString(text == name ? displayLabel(named) : text);
    if (!unitText(unit).isEmpty()) label += QStringLiteral(" [%1]").arg(unitText(unit));
    auto* result = new QTableWidgetItem(label);
    result->setToolTip(tr("%1: Σ %2 · %1 over the cases").arg(QString::fromStdString(name), QString::fromStdString(column)));
    // The sum as study.json holds it: the shortest text that reads back to the same double.
    auto* value = new QTableWidgetItem(sum && sum->value ? displayValue(Json(*sum->value)) : QStringLiteral("—"));
    value->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    QString missing;
    if (!sum) {
      missing = tr("all: run the study");
    } else if (!sum->missing.empty()) {
      std::map<QString, QStringList> why;
      for (const std::string& id : sum->missing) {
        const auto it = index_of.find(id);
        const StudySession::CaseOutcome* o = it == index_of.end() ? nullptr : &session_.outcome(it->second);
        const QString reason = !o                                               ? tr("not run")
                               : o->status == StudySession::Status::Pending     ? tr("not finished")
                               : o->status == StudySession::Status::Failed      ? tr("failed")
                               : o->status == StudySession::Status::Cancelled   ? tr("cancelled")
                                                                                : tr("finished without this result");
        why[reason] << QString::fromStdString(id);
      }
      QStringList parts;
      for (auto& [reason, ids] : why) {
        constexpr int kShownIds = 8;
        QString list = ids.mid(0, kShownIds).join(QStringLiteral(", "));
        if (ids.size() > kShownIds) list += tr(" and %n more", nullptr, static_cast<int>(ids.size() - kShownIds));
        parts << tr("%1: %2").arg(reason, list);
      }
      missing = parts.join(QStringLiteral("; "));
      value->setToolTip(tr("No sum while a case of weight > 0 has no value"));
    }
    weighted_table_->setItem(row, 0, result);
    weighted_table_->setItem(row, 1, value);
    weighted_table_->setItem(row, 2, new QTableWidgetItem(missing));
  }
  // As tall as its rows (a scatter diagram sums one or two results): the plot below keeps the rest.
  weighted_table_->setFixedHeight(weighted_table_->horizontalHeader()->sizeHint().height() +
                                  weighted_table_->rowCount() * weighted_table_->verticalHeader()->defaultSectionSize() +
                                  2 * weighted_table_->frameWidth());
}

bool StudyPanel::fixedDesign() const {
  return from_file_ && session_.isDefined() && (!session_.isGrid() || !session_.folder().isEmpty());
}

bool StudyPanel::addParameterDialog() {
  const SceneDefinition* scene = from_file_ ? session_.scene() : document_->scene();
  if (!scene || runner_->isRunning() || fixedDesign()) return false;
  std::vector<std::string> taken;
  for (const SweepRange& r : grid_) taken.push_back(r.path);
  const std::string path = parameter_prompt_(*scene, baseParameters(), taken);
  if (path.empty()) return false;
  QString why;
  const auto spec = parameterSpec(path, &why);
  if (!spec) {
    fail(tr("%1: %2").arg(QString::fromStdString(path), why));
    return false;
  }
  const Json* current = study::findParameterValue(baseParameters(), spec->path);
  const auto answer = sweep_prompt_(*spec, proposedSweep(*spec, current ? *current : Json()));
  if (!answer) return false;
  addParameter(answer->first);
  return true;
}

void StudyPanel::rebuildTable() {
  const QSignalBlocker block(table_);
  const SceneDefinition* scene = from_file_ ? session_.scene() : document_->scene();
  if (from_file_ && session_.isDefined())
  {
    QStringList varied;
    if (grid_.empty())
      for (const std::string& label : session_.parameterLabels()) varied << QString::fromStdString(label).toHtmlEscaped();
    base_->setText(tr("Base: <b>%1</b> (a %2 study%3)")
                       .arg(QString::fromStdString(session_.base().name).toHtmlEscaped(), session_.kindName(),
                            varied.isEmpty() ? QString() : tr(" of %1").arg(varied.join(QStringLiteral(", ")))));
  }
  else if (scene)
    base_->setText(tr("Base: the open scenario, <b>%1</b>").arg(QString::fromStdString(document_->scenario().name).toHtmlEscaped()));
  else
    base_->setText(tr("Open a scenario to build a study from it."));
  table_->setRowCount(static_cast<int>(grid_.size()));
  for (int row = 0; row < static_cast<int>(grid_.size()); ++row) {
    const SweepRange& r = grid_[row];
    QString problem;
    const auto spec = parameterSpec(r.path, &problem);
    if (spec) problem = sweepProblem(*spec, r);
    // A field by its label, a table cell by its column's, the table and the row ("Speed of current profile row 2"),
    // with the unit; the path in the tooltip either way (and in place of the label where the scene has none).
    auto* name = new QTableWidgetItem(spec ? studyAxisLabel(parameterLabel(*spec), spec->unit) : QString::fromStdString(r.path));
    name->setFlags(name->flags() & ~Qt::ItemIsEditable);
    table_->setItem(row, kParameter, name);
    table_->setItem(row, kFrom, new QTableWidgetItem(cellText(r.from)));
    table_->setItem(row, kTo, new QTableWidgetItem(cellText(r.to)));
    table_->setItem(row, kValues, new QTableWidgetItem(QString::number(r.count)));
    auto* spacing = new QComboBox(table_);
    spacing->addItems({tr("linear"), tr("log")});
    spacing->setCurrentIndex(r.log ? 1 : 0);
    connect(spacing, &QComboBox::currentIndexChanged, this, [this, path = r.path](int index) {
      for (SweepRange& g : grid_)
        if (g.path == path) g.log = index == 1;
      rebuildTable();
    });
    table_->setCellWidget(row, kSpacing, spacing);
    name->setToolTip(problem.isEmpty() ? QString::fromStdString(r.path)
                                       : tr("%1: %2").arg(QString::fromStdString(r.path), problem));
    if (!problem.isEmpty()) name->setForeground(QColor(0xd6, 0x27, 0x28));
  }
  updateButtons();
}

void StudyPanel::updateButtons() {
  const bool running = runner_->isRunning();
  const bool have_base = (from_file_ && session_.isDefined()) || document_->isValid();
  const bool folder = from_file_ && !session_.folder().isEmpty();
  run_->setEnabled(!running && have_base && (!grid_.empty() || from_file_) && !folder);
  run_->setToolTip(folder ? tr("A study folder is run by maris-cli: `maris-cli study run STUDY --out %1 --resume` runs "
                               "its missing cases, then open the folder again").arg(session_.folder())
                          : QString());
  cancel_->setEnabled(running);
  add_->setEnabled(!running && !fixedDesign());
  add_->setToolTip(fixedDesign() ? tr("A %1 study's cases are its design: start a new study from the open scenario "
                                      "to vary parameters here").arg(session_.kindName())
                                 : QString());
  // A table or a sample has no ranges to edit: its parameters are named above the table, which is then hidden.
  table_->setVisible(!fixedDesign());
  remove_->setEnabled(!running && !grid_.empty());
  if (weighted_action_) weighted_action_->setEnabled(!running && from_file_ && session_.isTable() && !folder);
  table_->setEnabled(!running);
  if (!running && grid_.empty() && !from_file_)
    summary_->setText(tr("Right-click a number field in the parameter editor: Sweep this parameter…"));
}

}  // namespace maris::ui
