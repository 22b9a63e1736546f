// Flexible bodies from NASTRAN decks in case files (`bulk_data`, docs/bulk-data.md): the deck
// lands in the body's FE model with GRID ids as node ids, the shipped deck case reads, reduces
// and builds, and bad `bulk_data` entries fail at their place in the case file.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "input_error_matchers.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"

namespace limber::io {
namespace {

using test::fails_at;
using test::location_of;

const std::string kDeck = std::string(LIMBER_CASES_DIR) + "/satellite_panel.bdf";

std::string panel_case(const std::string& bulk_data) {
  return "flexible_bodies:\n"
         "  panel:\n"
         "    bulk_data: " + bulk_data + "\n"
         "    node_sets: {root_edge: [5]}\n"
         "    modes: {normal: 2, attachment: [{nodes: root_edge, dofs: uz}]}\n";
}

TEST(BulkDataCase, TheDeckLandsInTheBodysModel) {
  const Case input = read_case_text(panel_case(kDeck), test::kCaseName);
  ASSERT_EQ(input.flexible_bodies.size(), 1u);
  const FlexibleBodyCase& body = input.flexible_bodies[0];
  EXPECT_EQ(body.model.node_count(), 117);
  EXPECT_EQ(body.model.shells.size(), 96u);
  // GRID 5 is the hinge-side edge midpoint (0, 0, 0); the attachment site refers to it.
  const int root = body.model.node_sets.at("root_edge").at(0);
  EXPECT_EQ(body.model.node_ids[root], 5);
  EXPECT_EQ(body.model.node_positions[root], Eigen::Vector3d(0.0, 0.0, 0.0));
  EXPECT_EQ(body.request.attachment_sites.at(0).node, root);
  // PSHELL 1 of the deck: T, 12I/T^3, TS/T, NSM; MAT1 1.
  const fe::ShellProperty& shell = body.model.shell_properties.at(0);
  EXPECT_EQ(shell.thickness, 0.0005);
  EXPECT_EQ(shell.bending_ratio, 7650.0);
  EXPECT_EQ(shell.shear_ratio, 0.31);
  EXPECT_EQ(shell.nonstructural_mass, 1.6);
  EXPECT_EQ(shell.material.youngs_modulus, 60e9);
  // The deck's EIGRL and PARAM are listed, not silently dropped.
  ASSERT_EQ(body.notices.size(), 1u);
  EXPECT_NE(body.notices[0].find("EIGRL (1 card"), std::string::npos) << body.notices[0];
}

TEST(BulkDataCase, TheShippedDeckCaseReadsReducesAndBuilds) {
  const Case input = read_case_file(std::string(LIMBER_CASES_DIR) + "/satellite_deployment_deck.yaml");
  ASSERT_TRUE(input.mechanism);
  const CaseReduction reduction = reduce_case(input, ReductionScope::kMechanismBodies);
  const BodyReduction* panel = reduction.find("panel");
  ASSERT_NE(panel, nullptr);
  // The base case's generated panel: first free-free modes 101.9 and 111.1 Hz (its header).
  EXPECT_NEAR(panel->result.mode_set.modes.at(0).frequency_hz, 101.9, 0.05);
  EXPECT_NEAR(panel->result.mode_set.modes.at(1).frequency_hz, 111.1, 0.05);
  EXPECT_NO_THROW(build_mechanism(input, reduction));
}

TEST(BulkDataCase, TheSpiderDeckCaseCarriesItsHingesThroughTheRigidElements) {
  const Case input = read_case_file(std::string(LIMBER_CASES_DIR) + "/satellite_deployment_spider.yaml");
  ASSERT_TRUE(input.mechanism);
  const CaseReduction reduction = reduce_case(input, ReductionScope::kMechanismBodies);
  const BodyReduction* panel = reduction.find("panel");
  ASSERT_NE(panel, nullptr);
  const modal::ModeSet& modes = panel->result.mode_set;
  // Still free-free with six rigid-body modes; constraints only raise eigenvalues (Rayleigh),
  // so the spiders' panel is at least as stiff as the plain deck's (101.9, 111.1 Hz).
  EXPECT_EQ(modes.rigid_modes.size(), 6u);
  EXPECT_GT(modes.modes.at(0).frequency_hz, 101.9);
  EXPECT_GT(modes.modes.at(1).frequency_hz, 111.08);
  // The hinge grid 1001 and the coincident edge grid 5 it holds move together in every mode.
  const fe::FeModel& model = input.flexible_bodies.at(0).model;
  const int hinge = model.node_sets.at("root_edge").at(0);
  ASSERT_EQ(model.node_ids[hinge], 1001);
  const int edge = static_cast<int>(std::find(model.node_ids.begin(), model.node_ids.end(), 5) - model.node_ids.begin());
  EXPECT_LT((modes.shapes.middleRows(6 * hinge, 6) - modes.shapes.middleRows(6 * edge, 6)).cwiseAbs().maxCoeff(),
            1e-12 * modes.shapes.cwiseAbs().maxCoeff());
  EXPECT_NO_THROW(build_mechanism(input, reduction));
}

TEST(BulkDataCase, BadEntriesFailAtTheirPlace) {
  // A deck that is not there: at the value.
  std::string text = panel_case("nowhere.bdf");
  EXPECT_TRUE(fails_at(text, location_of(text, "nowhere.bdf"), "no such file"));
  // A name too long for the file system (issue 31).
  text = panel_case(std::string(3000, 'd') + ".bdf");
  EXPECT_TRUE(fails_at(text, location_of(text, "ddd"),
                       "expected a bulk-data file, got '" + std::string(60, 'd') + "… (3004 bytes)' (file name too long)"));
  // Generated meshes besides a deck.
  text = "flexible_bodies:\n  panel:\n    plates: []\n    bulk_data: " + kDeck +
         "\n    modes: {normal: 2}\n";
  EXPECT_TRUE(fails_at(text, location_of(text, kDeck), "either 'bulk_data' or generated meshes"));
  // An SPC set the deck does not define: at `spc`.
  text = panel_case("{file: " + kDeck + ", spc: 4}");
  EXPECT_TRUE(fails_at(text, location_of(text, "4}"), "got 4; the deck defines none"));
  // An unknown key and a bad choice in the map form.
  text = panel_case("{file: " + kDeck + ", units: mm}");
  EXPECT_TRUE(fails_at(text, location_of(text, "units"), "units"));
  text = panel_case("{file: " + kDeck + ", unsupported_cards: ignore}");
  EXPECT_TRUE(fails_at(text, location_of(text, "ignore"), "warn"));
  // A GRID id the deck does not have.
  text = "flexible_bodies:\n  panel:\n    bulk_data: " + kDeck +
         "\n    node_sets: {tip: [999]}\n    modes: {normal: 2}\n";
  EXPECT_TRUE(fails_at(text, location_of(text, "999"), "node id 999"));
}

}  // namespace
}  // namespace limber::io
