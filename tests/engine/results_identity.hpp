// Bit-for-bit comparison of two finished runs. The live-results tests of every scene use it: listening to
// partial results only copies what the solver has, so a run with a partial sink must equal one without.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/results.hpp"

namespace maris::test {

// Equal sizes and every entry equal bit for bit; a failure names the quantity and the row.
inline void expectSameValues(const std::vector<double>& a, const std::vector<double>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << what << " row " << i;
}

// Scalars, tables, plots, 3D frames (points and colour scalars) and solver counts of two runs agree exactly;
// only the wall time is left out.
inline void expectIdenticalResults(const Results& a, const Results& b) {
  ASSERT_EQ(a.scalars.size(), b.scalars.size());
  for (std::size_t i = 0; i < a.scalars.size(); ++i) {
    EXPECT_EQ(a.scalars[i].name, b.scalars[i].name);
    EXPECT_EQ(a.scalars[i].value, b.scalars[i].value) << a.scalars[i].name;
  }
  ASSERT_EQ(a.tables.size(), b.tables.size());
  for (std::size_t t = 0; t < a.tables.size(); ++t) {
    ASSERT_EQ(a.tables[t].name, b.tables[t].name);
    ASSERT_EQ(a.tables[t].columns.size(), b.tables[t].columns.size()) << a.tables[t].name;
    for (std::size_t c = 0; c < a.tables[t].columns.size(); ++c) {
      EXPECT_EQ(a.tables[t].columns[c].name, b.tables[t].columns[c].name);
      expectSameValues(a.tables[t].columns[c].values, b.tables[t].columns[c].values,
                       a.tables[t].name + "." + a.tables[t].columns[c].name);
    }
  }
  ASSERT_EQ(a.plots.size(), b.plots.size());
  ASSERT_EQ(a.view.frames.size(), b.view.frames.size());
  for (std::size_t f = 0; f < a.view.frames.size(); ++f) {
    const auto& sa = a.view.frames[f].shapes;
    const auto& sb = b.view.frames[f].shapes;
    ASSERT_EQ(sa.size(), sb.size()) << "frame " << f;
    for (std::size_t s = 0; s < sa.size(); ++s) {
      ASSERT_EQ(sa[s].points.size(), sb[s].points.size()) << sa[s].name;
      for (std::size_t k = 0; k < sa[s].points.size(); ++k)
        ASSERT_EQ(sa[s].points[k], sb[s].points[k]) << "frame " << f << " " << sa[s].name << " point " << k;
      expectSameValues(sa[s].scalars, sb[s].scalars, "frame " + std::to_string(f) + " " + sa[s].name);
    }
  }
  EXPECT_EQ(a.stats.steps, b.stats.steps);
  EXPECT_EQ(a.stats.rhs_evaluations, b.stats.rhs_evaluations);
  EXPECT_EQ(a.stats.error_estimate, b.stats.error_estimate);
}

}  // namespace maris::test
