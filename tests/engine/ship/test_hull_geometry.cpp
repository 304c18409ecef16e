// Hull geometry: Wigley particulars in closed form, built-in and benchmark offsets tables against their
// published particulars (read from tests/data/hulls/*/particulars.json), and bad offsets tables.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "core/resources.hpp"
#include "ship/hull_form.hpp"
#include "ship/hull_offsets.hpp"
#include "hull_test_data.hpp"

using namespace maris;
using namespace maris::ship;

namespace {

std::string readHullFile(const std::string& relative) { return test_data::readHullFile(relative); }

nlohmann::json particularsJson(const std::string& hull) { return nlohmann::json::parse(readHullFile(hull + "/particulars.json")); }

HullParticulars particularsOf(const std::string& csv, const std::string& origin, double lpp, int nx = 257, int nz = 51) {
  const HullForm hull = makeOffsetsHull(origin, parseOffsetsCsv(csv, origin), lpp);
  return computeParticulars(sampleHull(hull, nx, nz), lpp);
}

std::string builtin(const char* path) { return std::string(*builtinResource(path)); }

}  // namespace

TEST(HullGeometry, WigleyParticularsMatchClosedForms) {
  // Y = (B/2)(1 − (2ξ/L)²)(1 − (z/T)²): ∇ = 4LBT/9, A_WP = 2LB/3, A_M = 2BT/3, so C_B = 4/9 and
  // C_P = C_M = C_WP = 2/3, LCB at midship. Simpson integrates the quadratics exactly: round-off (1e-12).
  const double L = 4.0, B = 0.4, T = 0.25;
  const HullParticulars p = computeParticulars(sampleHull(makeParametricHull(L, B, T), 257, 51), L);
  EXPECT_NEAR(p.volume, 4.0 * L * B * T / 9.0, 1e-12);
  EXPECT_NEAR(p.block_coefficient, 4.0 / 9.0, 1e-12);
  EXPECT_NEAR(p.prismatic_coefficient, 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(p.midship_coefficient, 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(p.waterplane_coefficient, 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(p.lcb_percent, 0.0, 1e-10);
  // KB: ∫(1 − z²/T²) z dz / ∫(1 − z²/T²) dz = −3T/8 below the waterline, i.e. 5T/8 above the keel.
  EXPECT_NEAR(p.kb, 5.0 * T / 8.0, 1e-12);
  EXPECT_NEAR(p.length_wl, L, 1e-12);
  EXPECT_NEAR(p.beam_wl, B, 1e-12);
  // S/L² = 0.1487906 (exact surface integral, evaluated independently). The triangulated grid surface converges at
  // second order; at 257×51 its error is below 2e-4 relative.
  EXPECT_NEAR(p.wetted_surface / (L * L), 0.1487906, 2e-4 * 0.1487906);
}

TEST(HullGeometry, Series60BuiltinTableMatchesPublishedParticulars) {
  // Todd (1963) parent 4210W: C_B 0.600, C_P 0.614, C_M 0.977, LCB 1.5 % Lpp aft (particulars.json
  // "published"). The table has only 6 underwater waterlines, so the monotone-cubic surface under-reads the
  // bilge: the hull data README measures C_B 0.5972 and C_M 0.9728 with the same interpolation (161×41,
  // Simpson). Tolerances: 0.1 % against that independent computation, 0.6 % against the published values.
  const auto j = particularsJson("series60_cb060");
  const HullParticulars p = particularsOf(builtin("data/ship/series60_cb060_offsets.csv"), "series60", 3.048);
  const auto& pub = j["published"];
  const auto& comp = j["computed"];
  EXPECT_NEAR(p.block_coefficient, comp["cb_pchip_161x41"].get<double>(), 1e-3 * 0.6);
  EXPECT_NEAR(p.midship_coefficient, comp["cm_pchip"].get<double>(), 1e-3);
  EXPECT_NEAR(p.block_coefficient, pub["cb"].get<double>(), 6e-3 * 0.6);
  EXPECT_NEAR(p.prismatic_coefficient, pub["cp"].get<double>(), 6e-3 * 0.614);
  EXPECT_NEAR(p.midship_coefficient, pub["cm"].get<double>(), 6e-3);
  // LCB: published −1.5 % (to 0.1 %), sectional-area column −1.484 %: 0.05 % Lpp.
  EXPECT_NEAR(p.lcb_percent, pub["lcb_from_midship_pct_lpp"].get<double>(), 0.05);
  EXPECT_NEAR(p.beam_wl, 3.048 / 7.5, 1e-6);
}

TEST(HullGeometry, KcsTablesMatchPublishedParticulars) {
  // KCS at model scale 1:31.5994, published ∇ 1.649 m³, C_B 0.6505, C_M 0.9849, LCB −1.48 % Lpp, S 9.4379 m²
  // without rudder (particulars.json). The sliced IGES itself gives S 1.3 % above the published value
  // (hull data README), so S is checked against the IGES value. Tolerances: the built-in 41×21 table has
  // stations 2.5 % of L apart (∇, C_M 0.3 %, LCB 0.1 % Lpp, S 1.5 %); the benchmark 161×41 table 0.15 % / 1 %.
  const auto j = particularsJson("kcs");
  const auto& pub = j["model_scale"]["published_model"];
  const double scale = j["model_scale"]["scale"].get<double>();
  const double lpp = 230.0 / scale, s_iges = j["model_scale"]["wetted_area_m2"].get<double>();
  struct Case {
    std::string csv, name;
    double tol, s_tol;
  };
  const Case cases[] = {{builtin("data/ship/kcs_model_offsets.csv"), "kcs 41x21", 3e-3, 1.5e-2},
                        {readHullFile("kcs/kcs_model_offsets_161x41.csv"), "kcs 161x41", 1.5e-3, 1e-2}};
  for (const auto& c : cases) {
    const HullParticulars p = particularsOf(c.csv, c.name, lpp);
    EXPECT_NEAR(p.volume, pub["volume_m3"].get<double>(), c.tol * 1.649) << c.name;
    const double cb_published_dims = p.volume / (lpp * pub["bwl_m"].get<double>() * pub["draft_m"].get<double>());
    EXPECT_NEAR(cb_published_dims, j["published"]["cb"].get<double>(), c.tol * 0.6505) << c.name;
    EXPECT_NEAR(p.midship_coefficient, j["published"]["cm"].get<double>(), c.tol) << c.name;
    EXPECT_NEAR(p.lcb_percent, j["published"]["lcb_from_midship_pct_lpp"].get<double>(), 0.1) << c.name;
    EXPECT_NEAR(p.wetted_surface, s_iges, c.s_tol * s_iges) << c.name;
    EXPECT_NEAR(p.draft, pub["draft_m"].get<double>(), 1e-4) << c.name;
    // A bulb: the body extends forward of the FP, so the FP section has area.
    EXPECT_GT(p.bulb_area, 0.0) << c.name;
  }
}

TEST(HullGeometry, BadOffsetsAreReportedByLineAndColumn) {
  const std::string csv =
      "x_m,z_m,half_breadth_m\n"
      "0,0,0.1\n0,-0.1,0.05\n"
      "1,0,\n1,-0.1,-0.02\n"       // line 4: missing half-breadth; line 5: negative
      "2,0,abc\n2,-0.1,0.0\n";     // line 6: not a number
  try {
    parseOffsetsCsv(csv, "parameters.hull.offsets_file");
    FAIL() << "bad offsets were accepted";
  } catch (const InputError& e) {
    const std::string all = describeErrors(e.errors());
    EXPECT_NE(all.find("line 4, column 3 (half_breadth_m): expected a number, found an empty cell"), std::string::npos) << all;
    EXPECT_NE(all.find("line 5, column 3 (half_breadth_m): is negative"), std::string::npos) << all;
    EXPECT_NE(all.find("line 6, column 3 (half_breadth_m): expected a number, found \"abc\""), std::string::npos) << all;
    EXPECT_EQ(e.errors().front().path, "parameters.hull.offsets_file");
  }
  EXPECT_THROW(parseOffsetsCsv("x,z,half_breadth\n0,0,1\n", "f"), InputError);  // no units
  EXPECT_THROW(parseOffsetsCsv("x_m,z_m,half_breadth_m\n0,0,1\n0,-1,1\n1,0,1\n1,-1,1\n", "f"), InputError);  // 2 stations
  EXPECT_NO_THROW(parseOffsetsCsv("x,z,half_breadth\nm,m,m\n0,0,1\n0,-1,1\n1,0,1\n1,-1,1\n2,0,0\n2,-1,0\n", "f"));
}

namespace {

// The benchmark 161×41 tables are sampled on 321×81 nodes, which contain the table's own nodes, so that the
// grid adds no error of its own at the stations and waterlines of the table.
HullParticulars benchmarkTableParticulars(const std::string& file, double lpp) {
  return particularsOf(readHullFile(file), file, lpp, 321, 81);
}

// Wetted surface of an interpolated offsets table against the exact surface it was sliced from: the monotone
// cubic surface between table nodes is slightly wavier than the real one and the grid triangles across a
// rising keel line count a sliver of centre plane, so S reads high. Measured on the DTC, KCS (+0.3 … 0.4 %,
// flat bottoms), DTMB 5415 (+1.8 %, sonar dome) and Sysser 1 (+1.4 %, rounded canoe body): the band is
// [−0.5 %, +2 %]. Use the published S (hull.wetted_surface) for coefficients.
void expectWettedSurfaceNear(double computed, double exact_surface, const std::string& hull) {
  EXPECT_GT(computed, exact_surface * (1.0 - 5e-3)) << hull;
  EXPECT_LT(computed, exact_surface * (1.0 + 2e-2)) << hull;
}

}  // namespace

TEST(HullGeometry, DtcTableMatchesPublishedParticulars) {
  // DTC model 1:59.407 (el Moctar et al. 2012, Table 1, divided by the scale; particulars.json "published").
  // The hull data README's hydrostatics of the exact STL differ from these by ≤ 0.08 % (∇, C_B) and 0.003 %
  // (LCB); the table adds its sampling error (stations 3.9 cm apart, waterlines 6 mm): 0.3 % on ∇ and C_B,
  // 0.1 % on B_WL and T (flat keel: the deepest row), 0.1 % Lpp on LCB.
  const auto j = particularsJson("dtc");
  const auto& pub = j["published"];
  const double lpp = pub["lpp_m"].get<double>();
  const HullParticulars p = benchmarkTableParticulars("dtc/dtc_model_offsets_161x41.csv", lpp);
  const double volume = pub["volume_m3"].get<double>();
  EXPECT_NEAR(p.volume, volume, 3e-3 * volume);
  expectWettedSurfaceNear(p.wetted_surface, j["computed"]["wetted_area_m2"].get<double>(), "dtc");
  EXPECT_NEAR(p.beam_wl, pub["bwl_m"].get<double>(), 1e-3 * 0.8585);
  EXPECT_NEAR(p.draft, pub["draft_m"].get<double>(), 1e-3 * 0.2441);
  EXPECT_NEAR(p.block_coefficient, pub["cb"].get<double>(), 3e-3 * 0.661);
  EXPECT_NEAR(p.lcb_from_ap, pub["lcb_from_ap_m"].get<double>(), 1e-3 * lpp);
  EXPECT_GT(p.bulb_area, 0.0);  // the bulb reaches forward of the FP
}

TEST(HullGeometry, Dtmb5415TableMatchesPublishedParticularsDespiteTheSonarDome) {
  // DTMB 5415 full scale (SIMMAN 2008: ∇ 8424.4 m³, C_B 0.506, C_M 0.816, T 6.15 m). The sonar dome reaches
  // 9.17 m below the waterline: the moulded draft must still be the midship keel at 6.15 m (within half a
  // waterline spacing, 0.057 m), not the dome. The STL is coarse (3436 facets): the hull data README measures
  // ∇ −0.45 % and C_M −0.08 % against the published values, so the tolerances are 0.8 % (∇, C_B) and 0.5 %
  // (C_M, with the published B and T); LCB is 0.21 % Lpp forward of the published value in the STL itself
  // (0.3 % Lpp here).
  const auto j = particularsJson("dtmb5415");
  const auto& pub = j["published"];
  const double lpp = pub["lpp_m"].get<double>(), T = pub["draft_m"].get<double>(), B = pub["bwl_m"].get<double>();
  const HullParticulars p = benchmarkTableParticulars("dtmb5415/dtmb5415_fullscale_offsets_161x41.csv", lpp);
  EXPECT_NEAR(p.max_depth, j["computed"]["t_max_m"].get<double>(), 1e-5 * 9.17);
  EXPECT_NEAR(p.draft, T, 0.5 * p.max_depth / 80.0);
  const double volume = pub["volume_m3"].get<double>();
  EXPECT_NEAR(p.volume, volume, 8e-3 * volume);
  expectWettedSurfaceNear(p.wetted_surface, j["computed"]["wetted_area_m2"].get<double>(), "dtmb5415");
  EXPECT_NEAR(p.volume / (lpp * B * T), pub["cb"].get<double>(), 8e-3 * 0.506);
  EXPECT_NEAR(p.max_section_area / (B * T), pub["cm"].get<double>(), 5e-3 * 0.816);
  EXPECT_NEAR(p.beam_wl, B, 1e-3 * B);
  EXPECT_NEAR(p.lcb_percent, pub["lcb_from_midship_pct_lpp"].get<double>(), 0.3);
}

TEST(HullGeometry, Sysser1YachtTableMatchesPublishedHydrostatics) {
  // Delft Systematic Yacht Hull Series, Sysser 1 canoe body (TU Delft 4TU.ResearchData CC0 release, row
  // Sysser = 1; particulars.json "published"). Reference length LWL 1.6 m; T_c is the canoe-body depth. The
  // hull data README finds ∇, A_WP and A_M within 0.2 % from the exact IGES surface but B_WL +1.1 % and S +2.1 %
  // (unexplained: possibly nominal values), so those two are checked against the IGES surface instead.
  // Tolerances add the table's sampling: 0.4 % (∇, A_WP, A_M), 0.3 % (B_WL against the IGES).
  const auto j = particularsJson("dsyhs_sysser01");
  const auto& pub = j["published"];
  const auto& iges = j["computed"];
  const double lwl = pub["lwl_m"].get<double>();
  const HullParticulars p = benchmarkTableParticulars("dsyhs_sysser01/sysser01_model_offsets_161x41.csv", lwl);
  const double volume = pub["volume_m3"].get<double>(), awp = pub["waterplane_area_m2"].get<double>();
  const double am = pub["max_section_area_m2"].get<double>();
  EXPECT_NEAR(p.volume, volume, 4e-3 * volume);
  EXPECT_NEAR(p.waterplane_area, awp, 4e-3 * awp);
  EXPECT_NEAR(p.max_section_area, am, 4e-3 * am);
  EXPECT_NEAR(p.draft, pub["draft_m"].get<double>(), 0.5 * p.max_depth / 80.0);
  EXPECT_NEAR(p.beam_wl, iges["bwl_m"].get<double>(), 3e-3 * 0.5129);
  expectWettedSurfaceNear(p.wetted_surface, iges["wetted_area_m2"].get<double>(), "sysser01");
  // LCB from mid-LWL: published −0.0366 m, IGES −0.0343 m (0.15 % LWL apart): within 0.3 % LWL.
  EXPECT_NEAR(p.lcb_from_ap - 0.5 * lwl, pub["lcb_from_mid_lwl_m"].get<double>(), 3e-3 * lwl);
}
