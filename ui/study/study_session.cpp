// StudySession: what the panel keeps of a study. The study file, the expansion and study.csv are
// the engine's (study_session_engine.cpp calls them); here are the outcomes and the plot data.
#include "study/study_session.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QStringList>

#include "study/study_session_impl.hpp"

namespace maris::ui {

int StudySession::caseCount() const { return impl_ ? static_cast<int>(impl_->cases.size()) : 0; }

const Scenario& StudySession::caseScenario(int index) const { return impl_->cases.at(index).scenario; }

QString StudySession::caseId(int index) const { return QString::fromStdString(impl_->cases.at(index).id); }

QString StudySession::caseLabel(int index) const {
  QStringList parts;
  const auto& c = impl_->cases.at(index);
  const auto& parameters = impl_->study.parameters;
  // Each value with the digits the plot's legend gives it: enough to tell this study's values apart.
  const auto valuesOf = [&](std::size_t p) {
    std::vector<double> values;
    values.reserve(impl_->cases.size());
    for (const auto& other : impl_->cases)
      values.push_back(p < other.values.size() && other.values[p].is_number() ? other.values[p].get<double>()
                                                                             : std::nan(""));
    return values;
  };
  if (impl_->value_digits.size() != parameters.size()) {
    impl_->value_digits.clear();
    for (std::size_t p = 0; p < parameters.size(); ++p)
      impl_->value_digits.push_back(
          studyValueDigits(StudyParameterData{parameters[p].path, parameters[p].label, parameters[p].unit, false, valuesOf(p)}));
  }
  for (std::size_t p = 0; p < parameters.size() && p < c.values.size(); ++p) {
    const auto& param = parameters[p];
    const StudyParameterData shown{param.path, param.label, param.unit, false, {}};
    if (c.values[p].is_number()) {
      parts << studyParameterValue(shown, c.values[p].get<double>(), impl_->value_digits[p]);
    } else {
      const QString value = c.values[p].is_string() ? QString::fromStdString(c.values[p].get<std::string>())
                                                    : QString::fromStdString(c.values[p].dump());
      parts << QStringLiteral("%1 = %2").arg(studyAxisLabel(shown), value);
    }
  }
  return parts.join(QStringLiteral(", "));
}

std::vector<Scenario> StudySession::caseScenarios() const {
  std::vector<Scenario> out;
  if (!impl_) return out;
  out.reserve(impl_->cases.size());
  for (const auto& c : impl_->cases) out.push_back(c.scenario);
  return out;
}

void StudySession::setOutcome(int index, CaseOutcome outcome) {
  if (index >= 0 && index < static_cast<int>(outcomes_.size())) outcomes_[index] = std::move(outcome);
}

void StudySession::markUnfinishedCancelled() {
  for (CaseOutcome& o : outcomes_)
    if (o.status == Status::Pending) o.status = Status::Cancelled;
}

std::vector<std::string> StudySession::resultNames() const {
  std::vector<std::string> names;
  // The results the study lists ("results") come first, so the plot opens on one of them.
  if (impl_)
    for (const std::string& name : impl_->study.results)
      if (std::any_of(outcomes_.begin(), outcomes_.end(), [&](const CaseOutcome& o) { return o.results && o.results->findScalar(name); }))
        names.push_back(name);
  for (const CaseOutcome& o : outcomes_) {
    if (!o.results) continue;
    for (const Scalar& s : o.results->scalars)
      if (std::find(names.begin(), names.end(), s.name) == names.end()) names.push_back(s.name);
  }
  return names;
}

std::string StudySession::resultLabel(const std::string& name) const {
  for (const CaseOutcome& o : outcomes_)
    if (const Scalar* s = o.results ? o.results->findScalar(name) : nullptr) return displayLabel(*s);
  return name;
}

StudyPlotData StudySession::plotData(const std::string& result) const {
  StudyPlotData data;
  if (!impl_) return data;
  data.result_name = result;
  data.title = base_.name + " — study of " + std::to_string(impl_->cases.size()) + " cases";
  const auto& parameters = impl_->study.parameters;
  for (std::size_t p = 0; p < parameters.size(); ++p) {
    if (parameters[p].kind != ParamKind::Real && parameters[p].kind != ParamKind::Integer) continue;  // not on an axis
    StudyParameterData param;
    param.name = parameters[p].path;
    param.label = parameters[p].label;
    param.unit = parameters[p].unit;
    param.log = p < impl_->log.size() && impl_->log[p];
    for (const auto& c : impl_->cases)
      param.values.push_back(p < c.values.size() && c.values[p].is_number() ? c.values[p].get<double>() : std::nan(""));
    data.parameters.push_back(std::move(param));
  }
  for (const CaseOutcome& o : outcomes_) {
    const Scalar* s = o.results ? o.results->findScalar(result) : nullptr;
    data.result.push_back(s ? s->value : std::numeric_limits<double>::quiet_NaN());
    if (s && data.result_unit.empty()) data.result_unit = s->unit;
    if (s && data.result_label.empty()) data.result_label = displayLabel(*s);
  }
  return data;
}

}  // namespace maris::ui
