// The PNG plots of `maris-cli study run` and `study collect` name the varied parameters for people: the title,
// the axes and the legend use the scene's labels and units ("Length L [m]", "Young's modulus E [Pa] = 7e+10", a
// table cell as "Arc length of probe row 1"), never a dotted path. What a plot says is read from the text
// chunks every PNG carries ("Title", "Axes", "Legend"), not from its pixels.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <regex>
#include <string>

#include <zlib.h>

#include "catalog.hpp"
#include "cli_runner.hpp"
#include "scratch_folder.hpp"
#include "study_cli_helpers.hpp"

namespace maris {

namespace fs = std::filesystem;

namespace {

std::uint32_t bigEndian(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

std::string inflateText(const std::string& compressed) {
  std::string out(1 << 16, '\0');
  uLongf size = out.size();
  if (uncompress(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(compressed.data()),
                 compressed.size()) != Z_OK)
    return "(damaged)";
  out.resize(size);
  return out;
}

// The text chunks of a PNG file (tEXt, zTXt, iTXt), by keyword.
std::map<std::string, std::string> pngTexts(const fs::path& file) {
  const std::string png = test::slurp(file);
  std::map<std::string, std::string> texts;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t length = bigEndian(png, at);
    const std::string type = png.substr(at + 4, 4);
    const std::string data = png.substr(at + 8, length);
    at += 12 + length;
    const auto zero = data.find('\0');
    if (zero == std::string::npos) continue;
    const std::string key = data.substr(0, zero);
    if (type == "tEXt") {
      texts[key] = data.substr(zero + 1);
    } else if (type == "zTXt") {
      texts[key] = inflateText(data.substr(zero + 2));
    } else if (type == "iTXt") {
      const bool compressed = data[zero + 1] != 0;
      const auto language_end = data.find('\0', zero + 3);
      const auto translated_end = data.find('\0', language_end + 1);
      const std::string text = data.substr(translated_end + 1);
      texts[key] = compressed ? inflateText(text) : text;
    }
  }
  return texts;
}

}  // namespace

class CliStudyLabels : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!findBuiltin("riser_cantilever_tip_load")) GTEST_SKIP() << "needs the riser scene";
#if !MARIS_TEST_PLOT_RENDERER
    GTEST_SKIP() << "this build has no plot renderer";
#endif
    dir_ = test::freshTestFolder("maris_cli_study_labels_");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Every plot of `plots`: its texts, each checked to hold no dotted path ("geometry.length": a letter, a dot, a
  // letter; numbers such as 2.1e+11 have digits there).
  static std::map<std::string, std::map<std::string, std::string>> plotTexts(const fs::path& plots) {
    std::map<std::string, std::map<std::string, std::string>> all;
    const std::regex dotted("[A-Za-z_]\\.[A-Za-z_]");
    for (const auto& e : fs::directory_iterator(plots)) {
      auto texts = pngTexts(e.path());
      for (const auto& [key, text] : texts)
        EXPECT_FALSE(std::regex_search(text, dotted)) << e.path().filename() << " " << key << ": " << text;
      all[e.path().filename().string()] = std::move(texts);
    }
    return all;
  }

  fs::path dir_;
};

// The cantilever over length and Young's modulus (a table cell, the first probe's arc length, at one value):
// three line plots of the bottom end's z, each titled, labelled and with legends in the schema's words.
TEST_F(CliStudyLabels, StudyPlotsNameParametersByTheirLabelsAndUnits) {
  test::writeText(dir_ / "labels.json", R"({"format": "maris-study/1", "base": "riser_cantilever_tip_load",
    "grid": {"geometry.length": [10, 20], "section.youngs_modulus": [7e10, 2.1e11],
             "output.probes[0].arc_length": [2]},
    "results": ["end_z"]})");
  const auto run = test::runCli({"study", "run", "labels.json", "--out", "out", "--jobs", "2"}, dir_.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const bool collected : {false, true}) {
    if (collected) {
      fs::remove_all(dir_ / "out" / "plots");
      const auto again = test::runCli({"study", "collect", "out"}, dir_.string());
      ASSERT_EQ(again.exit_code, 0) << again.err;
    }
    const auto plots = plotTexts(dir_ / "out" / "plots");
    ASSERT_EQ(plots.size(), 3u);
    const auto& length = plots.at("end_z_vs_geometry.length.png");
    EXPECT_EQ(length.at("Title"), "Bottom end z against Length L");
    EXPECT_EQ(length.at("Axes"), "Length L [m]\nBottom end z [m]");
    // A line per Young's modulus (the probe's one value in every legend entry; the parameters in the order of
    // their paths), 4 significant digits.
    EXPECT_EQ(length.at("Legend"),
              "Arc length of probe row 1 [m] = 2, Young's modulus E [Pa] = 7e+10\n"
              "Arc length of probe row 1 [m] = 2, Young's modulus E [Pa] = 2.1e+11");
    const auto& modulus = plots.at("end_z_vs_section.youngs_modulus.png");
    EXPECT_EQ(modulus.at("Title"), "Bottom end z against Young's modulus E");
    EXPECT_EQ(modulus.at("Axes"), "Young's modulus E [Pa]\nBottom end z [m]");
    const auto& cell = plots.at("end_z_vs_output.probes_0.arc_length.png");
    EXPECT_EQ(cell.at("Title"), "Bottom end z against Arc length of probe row 1");
    EXPECT_EQ(cell.at("Axes"), "Arc length of probe row 1 [m]\nBottom end z [m]");
  }
  // study.csv keeps the paths: it is for programs.
  const std::string csv = test::slurp(dir_ / "out" / "study.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "case,status,geometry.length,output.probes[0].arc_length,section.youngs_modulus,end_z");
}

}  // namespace maris
