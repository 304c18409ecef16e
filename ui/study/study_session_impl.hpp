// StudySession's engine side: the engine's study (engine/study/study.hpp) and its expanded cases, plus
// the varied parameters' spacing for plots.
#pragma once

#include "study/study.hpp"
#include "study/study_session.hpp"

namespace maris::ui {

struct StudySession::Impl {
  study::Study study;
  std::vector<study::StudyCase> cases;
  std::vector<bool> log;  // per study.parameters: varied on a log scale
  // Per study.parameters: the significant digits that tell its values in `cases` apart (caseLabel), found on first
  // use; cleared wherever `cases` change.
  mutable std::vector<int> value_digits;
};

}  // namespace maris::ui
