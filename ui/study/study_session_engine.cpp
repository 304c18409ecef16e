// StudySession: the calls into the engine's study model (file, expansion and validation, study.csv).
#include <algorithm>

#include "core/errors.hpp"
#include "scene_library.hpp"
#include "study/study_session.hpp"
#include "study/study_session_impl.hpp"

namespace maris::ui {

namespace {

study::GridParameter toGrid(const SweepRange& r) {
  study::GridParameter g;
  g.path = r.path;
  g.from = r.from;
  g.to = r.to;
  g.count = r.count;
  g.log = r.log;
  return g;
}

// A grid entry as the panel edits it (an explicit list shows as its first and last value and count).
SweepRange toSweep(const study::GridParameter& g) {
  SweepRange r;
  r.path = g.path;
  if (g.values.empty()) {
    r.from = g.from;
    r.to = g.to;
    r.count = g.count;
    r.log = g.log;
  } else {
    r.from = g.values.front();
    r.to = g.values.back();
    r.count = static_cast<int>(g.values.size());
  }
  return r;
}

}  // namespace

void StudySession::define(const SceneDefinition& scene, const Scenario& base, std::vector<SweepRange> grid) {
  scene_ = std::make_shared<const SceneDefinition>(scene);
  base_ = base;
  grid_ = std::move(grid);
  // In the order of their paths, as a study file reads back (JSON objects keep no order).
  std::sort(grid_.begin(), grid_.end(), [](const SweepRange& a, const SweepRange& b) { return a.path < b.path; });
  impl_ = std::make_shared<Impl>();
  impl_->definition.name = base.name + " study";
  impl_->definition.base = base;
  for (const SweepRange& r : grid_) impl_->definition.grid.push_back(toGrid(r));
  outcomes_.clear();
}

void StudySession::load(const QString& file, const SceneLibrary& library) {
  auto builtin = [&library](const std::string& id) -> const Scenario* {
    const BuiltinScenario* found = library.findExample(id);
    return found ? &found->scenario : nullptr;
  };
  study::StudyDefinition definition = study::loadStudyFile(file.toStdString(), builtin);
  const SceneDefinition* scene = library.findScene(definition.base.scene);
  if (!scene) throw InputError("base.scene", definition.base.scene, "is not a scene of this program");
  upgradeParameters(*scene, definition.base.parameters);
  scene_ = std::make_shared<const SceneDefinition>(*scene);
  base_ = definition.base;
  grid_.clear();
  for (const study::GridParameter& g : definition.grid) grid_.push_back(toSweep(g));
  impl_ = std::make_shared<Impl>();
  impl_->definition = std::move(definition);
  outcomes_.clear();
}

void StudySession::save(const QString& file) const {
  if (!impl_) throw std::runtime_error("no study is defined");
  study::saveStudyFile(impl_->definition, file.toStdString());
}

QString StudySession::kindName() const { return QObject::tr("grid"); }

void StudySession::expand() {
  if (!impl_ || !scene_) throw std::runtime_error("no study is defined");
  impl_->cases.clear();
  impl_->parameters.clear();
  outcomes_.clear();
  impl_->cases = study::expandStudy(impl_->definition, *scene_);
  for (const study::GridParameter& g : impl_->definition.grid) {
    const ParamSpec* spec = scene_->schema.find(g.path);
    impl_->parameters.push_back({g.path, spec ? spec->unit : std::string(), g.log});
  }
  outcomes_.assign(impl_->cases.size(), CaseOutcome{});
}

void StudySession::writeCsv(const QString& file) const {
  if (!impl_ || impl_->cases.empty()) throw std::runtime_error("the study has no cases yet: run it first");
  std::vector<study::CaseResult> results;
  for (const CaseOutcome& o : outcomes_) {
    static const char* const names[] = {"pending", "ok", "failed", "cancelled"};
    results.push_back({names[static_cast<int>(o.status)], o.results.get()});
  }
  writeFileAtomic(file.toStdString(), study::studyCsv(impl_->definition, *scene_, impl_->cases, results));
}

}  // namespace maris::ui
