// Cross-checks: a deck and the generated mesh of the same structure give the same matrices
// and frequencies; a cantilever deck against Euler-Bernoulli closed forms; PBARL sections
// against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bulkdata/deck_parser.h"
#include "bulkdata/deck_to_fe.h"
#include "bulkdata/pbarl_section.h"
#include "deck_text.h"
#include "fe/assembly.h"
#include "fe/beam_section.h"
#include "fe/mesh_generators.h"
#include "modal/component_modes.h"

namespace limber::bulkdata {
namespace {

// Largest entry of |A - B| relative to the largest of |A|.
double relative_difference(const fe::SparseMatrix& a, const fe::SparseMatrix& b) {
  const Eigen::MatrixXd da(a), db(b);
  return (da - db).cwiseAbs().maxCoeff() / da.cwiseAbs().maxCoeff();
}

std::vector<double> frequencies(const fe::FeModel& model, int count) {
  modal::ModeRequest request;
  request.normal_count = count;
  const modal::ModalResult result = modal::compute_component_modes(model, request);
  EXPECT_EQ(result.status, modal::ModalStatus::kOk) << result.message;
  std::vector<double> hz;
  for (const modal::ModeInfo& mode : result.mode_set.modes) hz.push_back(mode.frequency_hz);
  return hz;
}

fe::FeModel from_deck(const std::string& path, const DeckOptions& options = {}) {
  fe::FeModelBuilder builder;
  add_deck(read_deck(path), options, builder);
  return std::move(builder).build();
}

fe::FeModel from_deck_text(const std::string& text, const DeckOptions& options = {}) {
  fe::FeModelBuilder builder;
  add_deck(parse_deck(read_cards_text(text, "deck.bdf"), "deck.bdf"), options, builder);
  return std::move(builder).build();
}

// The deck's positions are written with 4 decimals and the generator's are sums of binary
// fractions: nodes differ by ~1 ulp (1e-16 m), so K and M agree to ~1e-15 of their largest
// entries; 1e-12 leaves room for the element Jacobians' rounding. Frequencies of nearly
// equal matrices: the eigen-solver's own convergence (1e-10) dominates; 1e-8 bounds it.
constexpr double kMatrixTolerance = 1e-12;
constexpr double kFrequencyTolerance = 1e-8;

TEST(DeckCrossCheck, SatellitePanelDeckEqualsTheGeneratedPlate) {
  // cases/satellite_panel.bdf against the plate of cases/satellite_deployment.yaml.
  const fe::FeModel deck = from_deck(std::string(LIMBER_CASES_DIR) + "/satellite_panel.bdf");

  fe::FeModelBuilder builder;
  fe::ShellProperty property;
  property.material = {"cfrp_face", 60e9, 0.3, 1600.0};
  property.thickness = 0.0005;
  property.bending_ratio = 7650.0;
  property.shear_ratio = 0.31;
  property.nonstructural_mass = 1.6;
  fe::RectangularPlateMesh mesh;
  mesh.origin = {-0.4, 0.0, 0.0};
  mesh.edge_x = {0.8, 0.0, 0.0};
  mesh.edge_y = {0.0, 1.2, 0.0};
  mesh.elements_x = 8;
  mesh.elements_y = 12;
  mesh.property = builder.add_shell_property(property);
  fe::add_rectangular_plate(builder, mesh);
  const fe::FeModel generated = std::move(builder).build();

  // Same nodes (ids and positions), same elements.
  ASSERT_EQ(deck.node_ids, generated.node_ids);
  ASSERT_EQ(deck.shells.size(), generated.shells.size());
  for (int n = 0; n < deck.node_count(); ++n) {
    EXPECT_LT((deck.node_positions[n] - generated.node_positions[n]).norm(), 1e-15);
  }
  const fe::StructuralMatrices a = fe::assemble(deck);
  const fe::StructuralMatrices b = fe::assemble(generated);
  EXPECT_LT(relative_difference(a.stiffness, b.stiffness), kMatrixTolerance);
  EXPECT_LT(relative_difference(a.mass, b.mass), kMatrixTolerance);

  const std::vector<double> f_deck = frequencies(deck, 8);
  const std::vector<double> f_generated = frequencies(generated, 8);
  ASSERT_EQ(f_deck.size(), 8u);
  for (std::size_t i = 0; i < f_deck.size(); ++i) {
    EXPECT_NEAR(f_deck[i], f_generated[i], kFrequencyTolerance * f_generated[i]) << "mode " << i;
  }
}

// A steel cantilever, 1 m along x, 20 CBARs, clamped at grid 1 by SPC1 set 1; PBARL BAR with
// DIM1 = 10 mm (local z) and DIM2 = 20 mm (local y), v = basic y.
std::string cantilever_deck(test::FieldFormat format) {
  std::string text = "SOL 103\nCEND\nBEGIN BULK\n";
  text += test::card_text(format, {"MAT1", "1", "2.1+11", "", "0.3", "7850."});
  text += test::card_text(format, {"PBARL", "7", "1", "", "BAR", "", "", "", "", "0.01", "0.02"});
  for (int i = 0; i <= 20; ++i) {
    text += test::card_text(format, {"GRID", std::to_string(i + 1), "", fmt::format("{:.2f}", i / 20.0),
                                     "0.", "0."});
  }
  for (int i = 1; i <= 20; ++i) {
    text += test::card_text(format, {"CBAR", std::to_string(100 + i), "7", std::to_string(i),
                                     std::to_string(i + 1), "0.", "1.", "0."});
  }
  text += test::card_text(format, {"SPC1", "1", "123456", "1"});
  return text + "ENDDATA\n";
}

TEST(DeckCrossCheck, CantileverDeckEqualsTheGeneratedBeamAndTheClosedForm) {
  DeckOptions options;
  options.spc_set = 1;
  const fe::FeModel deck = from_deck_text(cantilever_deck(test::FieldFormat::kSmall), options);

  // The same beam generated: rectangle 20 mm along local y, 10 mm along local z.
  fe::FeModelBuilder builder;
  fe::BeamProperty property;
  property.material = {"steel", 2.1e11, 0.3, 7850.0};
  property.section = fe::rectangle_section(0.02, 0.01);
  fe::StraightBeamMesh mesh;
  mesh.start = {0.0, 0.0, 0.0};
  mesh.end = {1.0, 0.0, 0.0};
  mesh.elements = 20;
  mesh.orientation = {0.0, 1.0, 0.0};
  mesh.property = builder.add_beam_property(property);
  const std::vector<int> nodes = fe::add_straight_beam(builder, mesh);
  for (int k = 0; k < fe::kDofsPerNode; ++k) builder.fix(nodes[0], static_cast<fe::Dof>(k));
  const fe::FeModel generated = std::move(builder).build();

  ASSERT_EQ(deck.fixed_dofs.size(), 6u);
  const fe::StructuralMatrices a = fe::assemble(deck);
  const fe::StructuralMatrices b = fe::assemble(generated);
  EXPECT_LT(relative_difference(a.stiffness, b.stiffness), kMatrixTolerance);
  EXPECT_LT(relative_difference(a.mass, b.mass), kMatrixTolerance);

  // Euler-Bernoulli cantilever: f1 = (β1 L)² / (2π) sqrt(E I / (ρ A L⁴)), β1 L = 1.8751041.
  // Bending about local y (I2 = DIM2 DIM1³/12, out of the x-y plane) comes first, about
  // local z (I1 = DIM1 DIM2³/12) at twice the frequency. 20 cubic elements: discretisation
  // error ~1e-7; limber's rotary inertia ρI lowers f1 by ~(β1 r)²/2 ~ 1e-5 (r² = I/A); so 1e-4.
  const double area = 0.01 * 0.02;
  const double i2 = 0.02 * std::pow(0.01, 3) / 12.0;
  const double i1 = 0.01 * std::pow(0.02, 3) / 12.0;
  const double beta = 1.8751040687119611;
  const auto closed_form = [&](double inertia) {
    return beta * beta / (2.0 * std::numbers::pi) * std::sqrt(2.1e11 * inertia / (7850.0 * area));
  };
  const std::vector<double> f = frequencies(deck, 2);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_NEAR(f[0], closed_form(i2), 1e-4 * closed_form(i2));
  EXPECT_NEAR(f[1], closed_form(i1), 1e-4 * closed_form(i1));
}

TEST(DeckCrossCheck, SmallLargeAndFreeFieldDecksGiveTheSameModel) {
  DeckOptions options;
  options.spc_set = 1;
  const fe::FeModel small = from_deck_text(cantilever_deck(test::FieldFormat::kSmall), options);
  for (test::FieldFormat format : {test::FieldFormat::kLarge, test::FieldFormat::kFree}) {
    const fe::FeModel other = from_deck_text(cantilever_deck(format), options);
    EXPECT_EQ(other.node_positions, small.node_positions);
    ASSERT_EQ(other.beams.size(), small.beams.size());
    EXPECT_EQ(other.beam_properties.at(0).section.inertia_z, small.beam_properties.at(0).section.inertia_z);
    EXPECT_EQ(other.fixed_dofs.size(), small.fixed_dofs.size());
    EXPECT_EQ(relative_difference(fe::assemble(other).stiffness, fe::assemble(small).stiffness), 0.0);
  }
}

TEST(DeckCrossCheck, TriangleDeckEqualsTheBuildersTriangles) {
  // A 4 x 3 plate of CTRIA3 (two per square) and CQUAD4 on the last column.
  std::string text = "MAT1,1,7.+10,,0.3,2700.\nPSHELL,1,1,.002,1,,1\n";
  fe::FeModelBuilder builder;
  fe::ShellProperty property;
  property.material = {"MAT1 1", 7.0e10, 0.3, 2700.0};
  property.thickness = 0.002;
  const int pid = builder.add_shell_property(property);
  for (int j = 0; j <= 3; ++j) {
    for (int i = 0; i <= 4; ++i) {
      const int id = 1 + i + 5 * j;
      text += fmt::format("GRID,{},,{:.1f},{:.1f},0.\n", id, 0.1 * i, 0.1 * j);
      builder.add_node(id, {0.1 * i, 0.1 * j, 0.0});
    }
  }
  int eid = 1;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      const int n = i + 5 * j;  // index of grid n + 1
      text += fmt::format("CTRIA3,{},1,{},{},{}\n", eid++, n + 1, n + 2, n + 7);
      text += fmt::format("CTRIA3,{},1,{},{},{}\n", eid++, n + 1, n + 7, n + 6);
      builder.add_triangle({{n, n + 1, n + 6}, pid});
      builder.add_triangle({{n, n + 6, n + 5}, pid});
    }
  }
  for (int j = 0; j < 3; ++j) {
    const int n = 3 + 5 * j;
    text += fmt::format("CQUAD4,{},1,{},{},{},{}\n", eid++, n + 1, n + 2, n + 7, n + 6);
    builder.add_shell({{n, n + 1, n + 6, n + 5}, pid});
  }
  const fe::FeModel generated = std::move(builder).build();
  fe::FeModelBuilder from_deck;
  const std::vector<std::string> notices =
      add_deck(parse_deck(read_cards_text(text, "deck.bdf"), "deck.bdf"), {}, from_deck);
  const fe::FeModel deck = std::move(from_deck).build();
  ASSERT_EQ(deck.triangles.size(), 18u);
  ASSERT_EQ(deck.shells.size(), 3u);
  // Positions print exactly as 0.1 i rounds: the same matrices to round-off.
  EXPECT_LT(relative_difference(fe::assemble(deck).stiffness, fe::assemble(generated).stiffness),
            kMatrixTolerance);
  EXPECT_LT(relative_difference(fe::assemble(deck).mass, fe::assemble(generated).mass),
            kMatrixTolerance);
  // The notice says TS/T does not apply to triangles.
  ASSERT_FALSE(notices.empty());
  EXPECT_NE(notices.back().find("TS/T has no effect on triangles"), std::string::npos);
}

// Section formulas against closed forms: the same arithmetic in another order, with the
// cancellation of r² and bh³ differences (a digit or two): 1e-13 relative.
#define EXPECT_REL(actual, expected) EXPECT_NEAR(actual, expected, 1e-13 * std::abs(expected))

TEST(PbarlSection, TubeAndBoxAgainstClosedForms) {
  std::string error;
  // Tube ro = 50 mm, ri = 40 mm: A = π (ro² − ri²), I = π (ro⁴ − ri⁴)/4, J = 2 I (exact).
  const fe::BeamSection tube = pbarl_section("TUBE", {0.05, 0.04}, error);
  EXPECT_TRUE(error.empty());
  EXPECT_REL(tube.area, std::numbers::pi * 0.0009);
  EXPECT_REL(tube.inertia_y, std::numbers::pi * 3.69e-6 / 4.0);
  EXPECT_REL(tube.torsion_constant, std::numbers::pi * 3.69e-6 / 2.0);
  // Box b = 100 mm (z), h = 200 mm (y), walls t1 = 10 mm (top, bottom), t2 = 5 mm (sides):
  // A = b h − bi hi = 0.0038, I1 = (b h³ − bi hi³)/12, I2 = (h b³ − hi bi³)/12, and J by
  // Bredt's formula in its textbook form 4 Am² / ∮ ds/t, Am = (b − t2)(h − t1).
  const fe::BeamSection box = pbarl_section("BOX", {0.1, 0.2, 0.01, 0.005}, error);
  EXPECT_TRUE(error.empty());
  EXPECT_REL(box.area, 0.0038);
  EXPECT_REL(box.inertia_z, (0.1 * 0.008 - 0.09 * 0.18 * 0.18 * 0.18) / 12.0);
  EXPECT_REL(box.inertia_y, (0.2 * 0.001 - 0.18 * 0.09 * 0.09 * 0.09) / 12.0);
  const double am = 0.095 * 0.19;
  const double ds_over_t = 2.0 * 0.095 / 0.01 + 2.0 * 0.19 / 0.005;
  EXPECT_REL(box.torsion_constant, 4.0 * am * am / ds_over_t);
  // Bar: I1 = DIM1 DIM2³/12 (DIM2 along local y).
  const fe::BeamSection bar = pbarl_section("BAR", {0.01, 0.02}, error);
  EXPECT_REL(bar.inertia_z, 0.01 * 8e-6 / 12.0);
  EXPECT_REL(bar.inertia_y, 0.02 * 1e-6 / 12.0);
  // Inconsistent dimensions.
  pbarl_section("TUBE", {0.04, 0.05}, error);
  EXPECT_NE(error.find("inner radius"), std::string::npos);
}

}  // namespace
}  // namespace limber::bulkdata
