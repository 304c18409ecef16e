#include <gtest/gtest.h>

#include <string>

#include "core/text_format.hpp"

using maris::formatText;

// The conversions are printf's (C standard), so the expected texts are exact.
TEST(TextFormat, FormatsLikePrintf) {
  EXPECT_EQ(formatText("%.3g m", 1234.5), "1.23e+03 m");
  EXPECT_EQ(formatText("step %ld of %d: %s", 7L, 9, "ok"), "step 7 of 9: ok");
  EXPECT_EQ(formatText("%.6g %%", 0.1), "0.1 %");
  EXPECT_EQ(formatText("%s", ""), "");
}

// The old fixed buffers (64–640 characters) cut long messages; the text is sized to fit.
TEST(TextFormat, LongTextIsNotCut) {
  const std::string word(5000, 'x');
  const std::string out = formatText("[%s] %d", word.c_str(), 42);
  EXPECT_EQ(out.size(), 5000u + 5u);
  EXPECT_EQ(out.substr(out.size() - 4), "] 42");
}
