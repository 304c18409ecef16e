// StudySession's engine side: the study definition and its expanded cases (engine/study/), plus
// the varied parameters' names, units and spacing for plots.
#pragma once

#include "study/minimal_study.hpp"
#include "study/study_session.hpp"

namespace maris::ui {

struct StudySession::Impl {
  struct Parameter {
    std::string name;
    std::string unit;
    bool log = false;
  };
  study::StudyDefinition definition;
  std::vector<study::StudyCase> cases;
  std::vector<Parameter> parameters;
};

}  // namespace maris::ui
