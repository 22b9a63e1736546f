// PBARL I, CHAN, T and HAT sections (pbarl_section.h) against hand formulas written
// independently of the code's parallel-axis sums: the textbook I-beam and channel formulas
// (b h³ − (b − t_w)(h − 2 t_f)³)/12, and for unsymmetric shapes the moments ∫ y² dA, ∫ z² dA
// integrated strip by strip from the bottom (or the web's back) minus A times the centroid's
// distance squared. J is the open thin-walled Σ b t³/3.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bulkdata/pbarl_section.h"
#include "fe/section_outline.h"

namespace limber::bulkdata {
namespace {

fe::BeamSection section(const std::string& type, const std::vector<double>& dims) {
  std::string error;
  const fe::BeamSection s = pbarl_section(type, dims, error);
  EXPECT_TRUE(error.empty()) << error;
  EXPECT_EQ(pbarl_dimension_count(type), static_cast<int>(dims.size()));
  return s;
}

// Sums of a few products of millimetre-sized numbers: round-off ~1e-16 relative; 1e-12 is
// far below any formula error (a wrong term changes the result by percents).
void expect_relative(double value, double expected, const char* what) {
  EXPECT_NEAR(value, expected, 1e-12 * std::abs(expected)) << what;
}

TEST(PbarlSections, SymmetricIBeam) {
  const double h = 0.2, b = 0.1, tw = 0.006, tf = 0.01;
  const fe::BeamSection s = section("I", {h, b, b, tw, tf, tf});
  expect_relative(s.area, 2.0 * b * tf + tw * (h - 2.0 * tf), "A");
  expect_relative(s.inertia_z, (b * h * h * h - (b - tw) * std::pow(h - 2.0 * tf, 3)) / 12.0, "I1");
  expect_relative(s.inertia_y, (2.0 * tf * b * b * b + (h - 2.0 * tf) * tw * tw * tw) / 12.0, "I2");
  expect_relative(s.torsion_constant, (2.0 * b * tf * tf * tf + (h - 2.0 * tf) * tw * tw * tw) / 3.0, "J");
  expect_relative(s.fibre_y, h / 2.0, "fibre y");
}

TEST(PbarlSections, UnequalFlangeIBeam) {
  const double h = 0.3, b1 = 0.15, b2 = 0.08, tw = 0.008, t1 = 0.012, t2 = 0.009;
  const fe::BeamSection s = section("I", {h, b1, b2, tw, t1, t2});
  const double hw = h - t1 - t2;
  const double a = b1 * t1 + tw * hw + b2 * t2;
  // Strips from the bottom: ∫ y dA and ∫ y² dA.
  const double sy = b1 * t1 * t1 / 2.0 + tw * ((t1 + hw) * (t1 + hw) - t1 * t1) / 2.0 + b2 * (h * h - (h - t2) * (h - t2)) / 2.0;
  const double syy = b1 * std::pow(t1, 3) / 3.0 + tw * (std::pow(t1 + hw, 3) - std::pow(t1, 3)) / 3.0 +
                     b2 * (std::pow(h, 3) - std::pow(h - t2, 3)) / 3.0;
  const double yc = sy / a;
  expect_relative(s.area, a, "A");
  expect_relative(s.inertia_z, syy - a * yc * yc, "I1");
  expect_relative(s.inertia_y, (t1 * std::pow(b1, 3) + hw * std::pow(tw, 3) + t2 * std::pow(b2, 3)) / 12.0, "I2");
  expect_relative(s.fibre_y, std::max(yc, h - yc), "fibre y");
}

TEST(PbarlSections, Channel) {
  const double b = 0.05, h = 0.12, tw = 0.005, tf = 0.007;
  const fe::BeamSection s = section("CHAN", {b, h, tw, tf});
  const double a = 2.0 * b * tf + (h - 2.0 * tf) * tw;
  expect_relative(s.area, a, "A");
  expect_relative(s.inertia_z, (b * h * h * h - (b - tw) * std::pow(h - 2.0 * tf, 3)) / 12.0, "I1");
  // From the web's back: ∫ z dA, ∫ z² dA (web h x tw, flanges beyond it).
  const double sz = h * tw * tw / 2.0 + tf * (b * b - tw * tw);
  const double szz = h * std::pow(tw, 3) / 3.0 + 2.0 * tf * (std::pow(b, 3) - std::pow(tw, 3)) / 3.0;
  const double zc = sz / a;
  expect_relative(s.inertia_y, szz - a * zc * zc, "I2");
  expect_relative(s.torsion_constant, (h * std::pow(tw, 3) + 2.0 * (b - tw) * std::pow(tf, 3)) / 3.0, "J");
}

TEST(PbarlSections, TSection) {
  const double b = 0.1, h = 0.08, tf = 0.01, tw = 0.008;
  const fe::BeamSection s = section("T", {b, h, tf, tw});
  const double a = b * tf + (h - tf) * tw;
  const double sy = tw * (h - tf) * (h - tf) / 2.0 + b * (h * h - (h - tf) * (h - tf)) / 2.0;
  const double syy = tw * std::pow(h - tf, 3) / 3.0 + b * (std::pow(h, 3) - std::pow(h - tf, 3)) / 3.0;
  const double yc = sy / a;
  expect_relative(s.area, a, "A");
  expect_relative(s.inertia_z, syy - a * yc * yc, "I1");
  expect_relative(s.inertia_y, (tf * b * b * b + (h - tf) * tw * tw * tw) / 12.0, "I2");
  expect_relative(s.torsion_constant, (b * std::pow(tf, 3) + (h - tf) * std::pow(tw, 3)) / 3.0, "J");
}

TEST(PbarlSections, HatSection) {
  const double h = 0.04, t = 0.002, crown = 0.05, brim = 0.02;
  const fe::BeamSection s = section("HAT", {h, t, crown, brim});
  // Strips: bottom (two brims from the walls' inner faces out), two walls, the crown.
  const double c = crown / 2.0;
  const double a = 2.0 * (brim + t) * t + 2.0 * t * (h - 2.0 * t) + crown * t;
  const double sy = 2.0 * (brim + t) * t * t / 2.0 + 2.0 * t * ((h - t) * (h - t) - t * t) / 2.0 +
                    crown * (h * h - (h - t) * (h - t)) / 2.0;
  const double syy = 2.0 * (brim + t) * std::pow(t, 3) / 3.0 + 2.0 * t * (std::pow(h - t, 3) - std::pow(t, 3)) / 3.0 +
                     crown * (std::pow(h, 3) - std::pow(h - t, 3)) / 3.0;
  const double szz = 2.0 * t * (std::pow(c + brim, 3) - std::pow(c - t, 3)) / 3.0 +
                     2.0 * (h - 2.0 * t) * (std::pow(c, 3) - std::pow(c - t, 3)) / 3.0 + t * std::pow(crown, 3) / 12.0;
  const double yc = sy / a;
  expect_relative(s.area, a, "A");
  expect_relative(s.inertia_z, syy - a * yc * yc, "I1");
  expect_relative(s.inertia_y, szz, "I2");  // symmetric about y: centroid at z = 0
}

TEST(PbarlSections, OutlinesHaveTheSectionsAreaAndSecondMoments) {
  // The outline's shoelace integrals (fe/section_outline.h) against the section's parallel-axis
  // sums: two methods, exact for these polygons, so round-off only (1e-12 as above). Each
  // outline is about the centroid (first moments 0) on principal axes (product 0).
  const std::vector<std::pair<std::string, std::vector<double>>> cases{
      {"BAR", {0.02, 0.05}},
      {"BOX", {0.05, 0.08, 0.004, 0.003}},
      {"I", {0.3, 0.15, 0.08, 0.008, 0.012, 0.009}},
      {"CHAN", {0.05, 0.12, 0.005, 0.007}},
      {"T", {0.1, 0.08, 0.01, 0.006}},
      {"HAT", {0.04, 0.003, 0.05, 0.02}}};
  for (const auto& [type, dims] : cases) {
    const fe::BeamSection s = section(type, dims);
    const fe::PolygonProperties p = fe::polygon_properties(s.outline);
    EXPECT_FALSE(s.outline.equivalent) << type;
    expect_relative(p.area, s.area, (type + " A").c_str());
    expect_relative(p.inertia_z, s.inertia_z, (type + " I1").c_str());
    expect_relative(p.inertia_y, s.inertia_y, (type + " I2").c_str());
    EXPECT_NEAR(p.first_moment.norm(), 0.0, 1e-12 * s.area * std::sqrt(s.area)) << type;
    EXPECT_NEAR(p.product, 0.0, 1e-12 * (s.inertia_y + s.inertia_z)) << type;
  }
  // ROD and TUBE: inscribed 16-gons, 2.55 % short of the circle's area and 5.02 % of its I
  // (fe/section_outline.h; exact values in tests/fe/test_section_outline.cpp).
  for (const auto& [type, dims] :
       std::vector<std::pair<std::string, std::vector<double>>>{{"ROD", {0.01}}, {"TUBE", {0.02, 0.015}}}) {
    const fe::BeamSection s = section(type, dims);
    const fe::PolygonProperties p = fe::polygon_properties(s.outline);
    EXPECT_NEAR(p.area / s.area, 1.0, 0.03) << type;
    EXPECT_NEAR(p.inertia_z / s.inertia_z, 1.0, 0.06) << type;
    EXPECT_EQ(s.outline.hollow, type == "TUBE");
  }
}

TEST(PbarlSections, InconsistentDimensionsAreRefused) {
  std::string error;
  pbarl_section("I", {0.1, 0.1, 0.1, 0.006, 0.06, 0.05}, error);
  EXPECT_NE(error.find("expected flanges thinner than the height"), std::string::npos) << error;
  pbarl_section("CHAN", {0.05, 0.1, 0.06, 0.01}, error);
  EXPECT_NE(error.find("expected a web thinner than the width"), std::string::npos) << error;
  pbarl_section("T", {0.1, 0.05, 0.06, 0.01}, error);
  EXPECT_NE(error.find("expected a flange thinner than the height"), std::string::npos) << error;
  pbarl_section("HAT", {0.04, 0.03, 0.05, 0.02}, error);
  EXPECT_NE(error.find("expected walls thinner"), std::string::npos) << error;
  EXPECT_EQ(pbarl_dimension_count("L"), 0);  // unsymmetric (I12 != 0): not supported
}

}  // namespace
}  // namespace limber::bulkdata
