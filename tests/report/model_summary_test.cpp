// The summary's model (issue 28): body masses read back from results.h5, the momentum drift of a
// free-floating system against a hand calculation, and mode tables one per distinct component
// with static modes told by the joints at their node.
#include "mode_origins.h"
#include "model_description.h"
#include "momentum_drift.h"
#include "report_test_util.h"
#include "run_data.h"
#include "report_html.h"
#include "run_summary.h"
#include "results/results_writer.h"

#include <gtest/gtest.h>

namespace limber::report {
namespace {

using testing::fresh_directory;

// Two rigid bodies, a (1 kg at the origin) and b (3 kg at x = 2 m), with no joint; three samples
// of kinetic energy (peak 2 J) and momentum going from P = (1, 0, 0) kg m/s, L = 0 to
// P = (1.001, 0, 0), L = (0, 0, 0.002) kg m²/s. Options: a joint to ground, a falling gravity
// energy.
std::filesystem::path free_pair(const std::string& name, bool grounded, bool gravity) {
  const auto dir = fresh_directory(name);
  results::ResultsWriter writer(dir, "free pair", "model_summary_test.cpp");
  results::MassProperties a{1.0, Eigen::Vector3d(0.1, 0, 0), Eigen::Matrix3d::Identity()};
  results::MassProperties b{3.0, Eigen::Vector3d::Zero(), 2.0 * Eigen::Matrix3d::Identity()};
  writer.add_rigid_body({"a", {}, a});
  writer.add_rigid_body({"b", {}, b});
  if (grounded) writer.add_joint({"G", "spherical", "ground", "a"});
  writer.add_energy("kinetic");
  writer.add_energy("gravity");
  writer.record_momentum();
  for (int k = 0; k < 3; ++k) {
    results::Sample sample;
    sample.time = 0.5 * k;
    sample.bodies.resize(2);
    sample.bodies[1].position = Eigen::Vector3d(2, 0, 0);
    if (grounded) sample.joints.emplace_back();
    sample.energies = {k == 1 ? 2.0 : 1.0, gravity ? -1.0 * k : 0.0};
    sample.momentum << 1.0 + 0.0005 * k, 0, 0, 0, 0, 0.001 * k;
    writer.append_sample(sample);
  }
  writer.finish(results::RunStatus::kOk);
  return dir;
}

TEST(ModelSummary, MassesReadBackAndTheMomentumDriftMatchesTheHandCalculation) {
  const RunData run = read_run_data(free_pair("free_pair", false, false));
  ASSERT_EQ(run.body_masses.size(), 2u);
  EXPECT_EQ(run.body_masses[0].mass, 1.0);
  EXPECT_EQ(run.body_masses[0].com_B, Eigen::Vector3d(0.1, 0, 0));
  EXPECT_EQ(run.body_masses[1].inertia_com_B, 2.0 * Eigen::Matrix3d::Identity());
  const RunDigest d = digest_run(run);
  ASSERT_TRUE(d.total_mass.has_value());
  EXPECT_EQ(*d.total_mass, 4.0);
  // By hand: |ΔP| = 0.001 kg m/s, |ΔL| = 0.002 kg m²/s. Scales: sqrt(2 m T_peak) =
  // sqrt(2 · 4 · 2) = 4 kg m/s (above |P_first| = 1), times the size 2 m: 8 kg m²/s. Both
  // relative drifts 2.5e-4. Sums and a square root of exact binary numbers: to rounding.
  ASSERT_TRUE(d.momentum.has_value());
  EXPECT_NEAR(d.momentum->linear, 0.001, 1e-15);
  EXPECT_NEAR(d.momentum->angular, 0.002, 1e-15);
  EXPECT_DOUBLE_EQ(d.momentum->linear_scale, 4.0);
  EXPECT_DOUBLE_EQ(d.momentum->angular_scale, 8.0);
  EXPECT_NEAR(d.momentum->linear_relative(), 2.5e-4, 1e-15);
  EXPECT_NEAR(d.momentum->angular_relative(), 2.5e-4, 1e-15);

  // Not free-floating: a joint to ground, or gravity doing work. No drift is claimed.
  EXPECT_FALSE(momentum_drift(read_run_data(free_pair("grounded_pair", true, false))).has_value());
  EXPECT_FALSE(momentum_drift(read_run_data(free_pair("falling_pair", false, true))).has_value());
}

// Two flexible bodies of one component "panel" (nodes 1 and 10001; a normal and an attachment
// mode at node 10001), B1a at the origin and B1b at x = 5 m, with joint R1 at B1a's node 10001
// and R2 at B1b's.
TEST(ModelSummary, BodiesSharingAComponentShareOneModeTableWithStaticModesToldByJoint) {
  const auto dir = fresh_directory("shared_component");
  {
    results::ResultsWriter writer(dir, "panels", "model_summary_test.cpp");
    for (const char* name : {"B1a", "B1b"}) {
      results::FlexibleBodySpec body;
      body.name = name;
      body.nodes.resize(2, 3);
      body.nodes << 0, 0, 0, 0, 1.2, 0;
      body.node_ids = {1, 10001};
      body.mode_translations = Eigen::MatrixXd::Identity(6, 2);
      body.frequencies_hz = Eigen::Vector2d(3.0, 1100.0);
      body.mode_kinds = {"normal", "attachment"};
      body.mode_labels = {"normal 1", "attachment uz at node 10001"};
      body.component = "panel";
      writer.add_flexible_body(body);
    }
    writer.add_joint({"R1", "revolute", "ground", "B1a"});
    writer.add_joint({"R2", "revolute", "ground", "B1b"});
    results::Sample sample;
    sample.bodies.resize(2);
    for (results::BodySample& b : sample.bodies) b.modal_coordinates = b.modal_velocities = Eigen::Vector2d::Zero();
    sample.bodies[1].position = Eigen::Vector3d(5, 0, 0);
    sample.joints.resize(2);
    sample.joints[0].position = Eigen::Vector3d(0, 1.2, 0);
    sample.joints[1].position = Eigen::Vector3d(5, 1.2, 0);
    writer.append_sample(sample);
    writer.finish(results::RunStatus::kOk);
  }
  const RunData run = read_run_data(dir);
  ASSERT_EQ(run.mode_tables.size(), 1u);
  const ModeTable& table = run.mode_tables[0];
  EXPECT_EQ(table.bodies, (std::vector<std::string>{"B1a", "B1b"}));
  EXPECT_EQ(table.component, "panel");
  EXPECT_EQ(table.source, "results.h5");
  ASSERT_EQ(table.modes.size(), 2u);
  EXPECT_EQ(table.modes[1].kind, "attachment");
  EXPECT_EQ(mode_origin_joints(run, table, table.modes[1].label), "R1 on B1a, R2 on B1b");
  EXPECT_EQ(mode_origin_joints(run, table, table.modes[0].label), "");
  EXPECT_EQ(mode_table_of(run, "B1b"), &table);
}

// A nonlinear body (formulation: nonlinear: its nodes stored one by one, no modes; 2 beams over
// 3 nodes) beside a rigid one: the model line, the bodies table and the mode tables say what it
// is, not "0 modes".
TEST(ModelSummary, NonlinearBodyIsDescribedByItsElementsNotByModes) {
  const auto dir = fresh_directory("nonlinear_body");
  {
    results::ResultsWriter writer(dir, "rod", "model_summary_test.cpp");
    writer.add_rigid_body({"crank", {}, {}});
    results::FlexibleBodySpec rod;
    rod.name = "rod";
    rod.nodes.resize(3, 3);
    rod.nodes << 0, 0, 0, 0.5, 0, 0, 1, 0, 0;
    rod.lines.resize(2, 2);
    rod.lines << 0, 1, 1, 2;
    rod.mode_translations.resize(9, 0);
    rod.has_node_displacements = true;
    rod.component = "rod";
    writer.add_flexible_body(rod);
    results::Sample sample;
    sample.bodies.resize(2);
    sample.bodies[1].modal_coordinates.resize(0);
    sample.bodies[1].modal_velocities.resize(0);
    sample.bodies[1].node_displacements = Eigen::VectorXd::Zero(9);
    writer.append_sample(sample);
    writer.finish(results::RunStatus::kOk);
  }
  RunData run = read_run_data(dir);
  ASSERT_EQ(run.results.bodies.size(), 2u);
  EXPECT_FALSE(is_nonlinear(run.results.bodies[0]));
  ASSERT_TRUE(is_nonlinear(run.results.bodies[1]));
  EXPECT_EQ(nonlinear_description(run.results.bodies[1]), "nonlinear, 2 beam elements (3 nodes)");
  EXPECT_TRUE(run.mode_tables.empty());
  EXPECT_EQ(mode_table_of(run, "rod"), nullptr);

  ReportContent content;
  RunSection section;
  section.run = &run;
  section.label = "run 1: rod";
  section.anchor = "run1";
  content.runs.push_back(section);
  const std::string summary = summary_section(content);
  EXPECT_NE(summary.find("1 rigid and 1 flexible (rod: nonlinear, 2 beam elements (3 nodes))"), std::string::npos)
      << summary;
  EXPECT_EQ(summary.find("0 modes"), std::string::npos) << summary;
  const std::string html = report_html(content);
  EXPECT_NE(html.find("<td>rod</td><td>flexible, nonlinear</td><td class=\"number\">3</td><td class=\"number\">2</td>"
                      "<td class=\"number\">0</td><td class=\"number\">none (unreduced)</td>"),
            std::string::npos);
  EXPECT_NE(html.find("No modes: nonlinear, 2 beam elements (3 nodes), integrated unreduced."), std::string::npos);
  EXPECT_EQ(html.find("0 modes"), std::string::npos);
}

}  // namespace
}  // namespace limber::report
