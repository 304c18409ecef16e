// Schema validation: every bad field is reported with its path, value and allowed range.
#include <gtest/gtest.h>

#include "core/schema_binder.hpp"

namespace maris {
namespace {

struct LayerRow {
  double thickness = 2.0;  // [m]
  std::string material = "sand";
};

struct DemoParameters {
  double length = 100.0;             // [m]
  int segment_count = 20;            // [-]
  bool torsion = true;
  std::string formulation = "joint";
  std::string label = "demo";
  std::vector<double> output_times{1.0, 2.0};  // [s]
  std::vector<LayerRow> layers{LayerRow{}, LayerRow{3.0, "clay"}};
};

SchemaBinder<DemoParameters> demoBinder() {
  SchemaBinder<LayerRow> row;
  row.real("thickness", &LayerRow::thickness, "m", Range::positive(1e3), "Layer thickness");
  row.choice("material", &LayerRow::material, {"sand", "clay"}, "Material");
  SchemaBinder<DemoParameters> b;
  b.real("geometry.length", &DemoParameters::length, "m", Range::positive(1e5), "Length");
  b.integer("geometry.segment_count", &DemoParameters::segment_count, "-", Range::closed(2, 5000), "Segments");
  b.boolean("model.torsion", &DemoParameters::torsion, "Torsion on");
  b.choice("model.formulation", &DemoParameters::formulation, {"joint", "absolute"}, "Coordinates");
  b.text("label", &DemoParameters::label, "A label");
  b.realList("output.times", &DemoParameters::output_times, "s", Range::nonNegative(), 0, 10, "Output times");
  b.table("layers", &DemoParameters::layers, row, 1, 5, "Soil layers");
  return b;
}

bool hasError(const std::vector<FieldError>& errors, const std::string& path, const std::string& fragment) {
  for (const auto& e : errors)
    if (e.path == path && e.message.find(fragment) != std::string::npos) return true;
  return false;
}

TEST(Schema, DefaultsComeFromTheStructAndValidate) {
  const auto b = demoBinder();
  const Json defaults = b.schema().defaults();
  EXPECT_EQ(defaults["geometry"]["length"], 100.0);
  EXPECT_EQ(defaults["layers"][1]["material"], "clay");
  EXPECT_TRUE(validateAgainstSchema(b.schema(), defaults).empty());
}

TEST(Schema, ReadWriteRoundTripsEveryKind) {
  const auto b = demoBinder();
  DemoParameters p;
  p.length = 42.5;
  p.segment_count = 7;
  p.torsion = false;
  p.formulation = "absolute";
  p.output_times = {0.5};
  p.layers = {LayerRow{9.0, "sand"}};
  const Json j = b.write(p);
  ASSERT_TRUE(validateAgainstSchema(b.schema(), j).empty());
  const DemoParameters q = b.read(j);
  EXPECT_EQ(q.length, 42.5);
  EXPECT_EQ(q.segment_count, 7);
  EXPECT_FALSE(q.torsion);
  EXPECT_EQ(q.formulation, "absolute");
  EXPECT_EQ(q.output_times, std::vector<double>{0.5});
  ASSERT_EQ(q.layers.size(), 1u);
  EXPECT_EQ(q.layers[0].thickness, 9.0);
  EXPECT_EQ(b.write(q), j);
}

TEST(Schema, ReportsEveryBadFieldNotJustTheFirst) {
  const auto b = demoBinder();
  Json j = b.schema().defaults();
  j["geometry"]["length"] = -3.0;                 // out of range
  j["geometry"]["segment_count"] = 2.5;           // not an integer
  j["model"]["torsion"] = "yes";                  // wrong type
  j["model"]["formulation"] = "relative";         // not a choice
  j["output"]["times"] = Json::array({1.0, -1.0});  // bad element
  j["layers"][1]["thickness"] = 0.0;              // bad table cell
  j["geometry"]["lenght"] = 5.0;                  // unknown, misspelt
  j.erase("label");                               // missing
  const auto errors = validateAgainstSchema(b.schema(), j);
  EXPECT_EQ(errors.size(), 8u) << describeErrors(errors);
  EXPECT_TRUE(hasError(errors, "parameters.geometry.length", "(0, 100000] m"));
  EXPECT_TRUE(hasError(errors, "parameters.geometry.segment_count", "whole number"));
  EXPECT_TRUE(hasError(errors, "parameters.model.torsion", "true or false"));
  EXPECT_TRUE(hasError(errors, "parameters.model.formulation", "\"joint\", \"absolute\""));
  EXPECT_TRUE(hasError(errors, "parameters.output.times[1]", ">= 0"));
  EXPECT_TRUE(hasError(errors, "parameters.layers[1].thickness", "(0, 1000]"));
  EXPECT_TRUE(hasError(errors, "parameters.geometry.lenght", "did you mean 'geometry.length'"));
  EXPECT_TRUE(hasError(errors, "parameters.label", "missing"));
}

TEST(Schema, ErrorTextNamesPathValueAndRange) {
  const auto b = demoBinder();
  Json j = b.schema().defaults();
  j["geometry"]["segment_count"] = 1;
  const auto errors = validateAgainstSchema(b.schema(), j);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].str(), "parameters.geometry.segment_count = 1: must be in [2, 5000]");
}

TEST(Schema, NanAndInfinityAsStringsAreRejected) {
  const auto b = demoBinder();
  Json j = b.schema().defaults();
  j["geometry"]["length"] = "NaN";
  j["layers"][0]["thickness"] = "inf";
  const auto errors = validateAgainstSchema(b.schema(), j);
  EXPECT_TRUE(hasError(errors, "parameters.geometry.length", "must be a number"));
  EXPECT_TRUE(hasError(errors, "parameters.layers[0].thickness", "must be a number"));
}

TEST(Schema, TableRowCountAndRowShapeAreChecked) {
  const auto b = demoBinder();
  Json j = b.schema().defaults();
  j["layers"] = Json::array();
  EXPECT_TRUE(hasError(validateAgainstSchema(b.schema(), j), "parameters.layers", "between 1 and 5 rows"));
  j["layers"] = Json::array({42});
  EXPECT_TRUE(hasError(validateAgainstSchema(b.schema(), j), "parameters.layers[0]", "must be an object"));
  j["layers"] = Json::array({{{"thickness", 1.0}, {"material", "sand"}, {"colour", "red"}}});
  EXPECT_TRUE(hasError(validateAgainstSchema(b.schema(), j), "parameters.layers[0].colour", "unknown field"));
}

TEST(Schema, GroupThatIsNotAnObjectIsAnError) {
  const auto b = demoBinder();
  Json j = b.schema().defaults();
  j["geometry"] = 3;
  const auto errors = validateAgainstSchema(b.schema(), j);
  EXPECT_TRUE(hasError(errors, "parameters.geometry", "group of fields"));
}

TEST(Schema, RangeTextShowsOpenAndClosedEnds) {
  EXPECT_EQ(Range::positive(1e5).str(), "(0, 100000]");
  EXPECT_EQ(Range::closed(2, 5000).str(), "[2, 5000]");
  EXPECT_EQ(Range::nonNegative().str(), ">= 0");
  EXPECT_EQ(Range::any().str(), "any finite number");
  EXPECT_FALSE(Range::positive().contains(0.0));
  EXPECT_TRUE(Range::nonNegative().contains(0.0));
  EXPECT_FALSE(Range::any().contains(std::nan("")));
}

TEST(Schema, DidYouMeanSuggestsOnlyCloseWords) {
  EXPECT_EQ(didYouMean("lenght", {"length", "width"}), "length");
  EXPECT_EQ(didYouMean("zzzzzzzz", {"length", "width"}), "");
}

TEST(Schema, DescriptionListsUnitsDefaultsAndRanges) {
  const auto text = describeSchema(demoBinder().schema());
  EXPECT_NE(text.find("geometry.length  [m]  number in (0, 100000], default 100.0"), std::string::npos) << text;
  const Json j = schemaToJson(demoBinder().schema());
  EXPECT_EQ(j[0]["unit"], "m");
  EXPECT_EQ(j[0]["max"], 1e5);
  EXPECT_EQ(j[6]["columns"][0]["path"], "thickness");
}

}  // namespace
}  // namespace maris
