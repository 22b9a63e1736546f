// Reactions on a flexible body in its own axes (reaction_ranking.h), against the joint-frame
// reactions that results.h5 holds, on the coarse flexible slider-crank.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "coarse_slider_crank.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "run/run_driver.h"
#include "select/reaction_ranking.h"

namespace limber::select {
namespace {

TEST(ReactionRanking, BodyAxesAgreeWithTheJointFrameFixedToTheRod) {
  // The joint frame is marker j's axes. R2's marker j sits on the rod (node 1): its axes are
  // the rod's FE axes turned by the node's small elastic rotation, x_M = x_B, y_M = -z_B,
  // z_M = y_B (cases/slider_crank.yaml), and the results hold the reaction on the rod (body j).
  // So F_B = exp([θ]×) (F_x, F_z, -F_y)_joint with θ = Φ_r η at node 1 (flexible_marker.h):
  // equal to rounding (bound 1e-9 of the force; θ reaches ~1e-2 rad here, so leaving it out
  // would fail by ~20 N). R3's marker j is on the slider, against which the rod swings by up to
  // asin(a / b) = 0.05 rad: its joint frame is not the rod's, and the mapping must not be it.
  const io::Case input = io::read_case_text(test::coarse_slider_crank_text(), "coarse.yaml");
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const multibody::Model& model = built.model;
  const std::vector<JointOnFlexibleBody> sites = joints_on_flexible_bodies(model);
  ASSERT_EQ(sites.size(), 2u);  // R2 (rod is body j), R3 (rod is body i)
  EXPECT_EQ(model.joints[static_cast<std::size_t>(sites[0].joint)].name, "R2");
  EXPECT_EQ(sites[0].sign, 1.0);
  EXPECT_EQ(model.joints[static_cast<std::size_t>(sites[1].joint)].name, "R3");
  EXPECT_EQ(sites[1].sign, -1.0);
  EXPECT_EQ(sites[1].node, 20);

  io::RunSettings settings = built.run;
  settings.t_end = 0.15;
  double largest = 0.0, worst = 0.0, swing_largest = 0.0;
  run::RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample&, const results::Sample& record) {
    const Eigen::Matrix<double, 6, 1> on_rod = reaction_on_body(sites[0], record);
    const Eigen::Vector3d& f = record.joints[static_cast<std::size_t>(sites[0].joint)].force_joint;
    const auto& rod = *model.bodies[static_cast<std::size_t>(sites[0].body)].flexible;
    const Eigen::Vector3d theta = rod.shapes.block(3, 0, 3, rod.shapes.cols()) *
                                  record.bodies[static_cast<std::size_t>(sites[0].body - 1)].modal_coordinates;
    const Eigen::Matrix3d rotation =
        theta.norm() > 0.0 ? Eigen::AngleAxisd(theta.norm(), theta.normalized()).toRotationMatrix()
                           : Eigen::Matrix3d::Identity();
    const Eigen::Vector3d expected = rotation * Eigen::Vector3d(f.x(), f.z(), -f.y());
    largest = std::max(largest, f.norm());
    worst = std::max(worst, (on_rod.head<3>() - expected).norm());
    // R3 on the rod, against the slider's frame turned by the rod's swing angle ψ about y.
    const Eigen::Matrix<double, 6, 1> at_slider = reaction_on_body(sites[1], record);
    const Eigen::Vector3d& g = record.joints[static_cast<std::size_t>(sites[1].joint)].force_joint;
    swing_largest = std::max(swing_largest, (at_slider.head<3>() + Eigen::Vector3d(g.x(), g.z(), -g.y())).norm());
  };
  const run::RunSummary summary = run::run_mechanism(model, built.assembly, settings, hooks);
  ASSERT_TRUE(summary.ok) << summary.message;
  EXPECT_GT(largest, 1000.0);  // the rod's and slider's inertia load, about 2 kN
  EXPECT_LT(worst, 1e-9 * largest);
  // Ignoring the swing at R3 would be off by up to ψ |F| ~ 0.05 x 829 N: the check has teeth.
  EXPECT_GT(swing_largest, 10.0);
}

TEST(ReactionRanking, TorquesCountAsForcesAtTheBodysSize) {
  // Two sites' worth of columns on the coarse rod: R2 carries Fx = 100 N and Tz = 30 N m, R3
  // Fz = 5 N. The rod is 1 m (size = its bounding-box diagonal, 1 m for nodes on a line), so
  // Tz ranks as 30 N: 0.3 of the largest. With keep = 0.1: Fx and Tz kept, Fz (0.05) not.
  const io::Case input = io::read_case_text(test::coarse_slider_crank_text(), "coarse.yaml");
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const multibody::Model& model = built.model;
  Eigen::MatrixXd reactions = Eigen::MatrixXd::Zero(3, 12);
  reactions(1, 0) = -100.0;  // R2 Fx, peak 100 at the second sample
  reactions.col(5).setConstant(30.0);  // R2 Tz
  reactions(2, 8) = 5.0;  // R3 Fz
  const std::vector<RankedComponent> ranking =
      rank_reactions(model, reactions, {true, false}, RankBy::kPeak, 0.1);
  ASSERT_EQ(ranking.size(), 12u);
  EXPECT_EQ(ranking[0].label(), "R2.Fx");
  EXPECT_DOUBLE_EQ(ranking[0].peak, 100.0);
  EXPECT_NEAR(ranking[0].rms, 100.0 / std::sqrt(3.0), 1e-12);
  EXPECT_TRUE(ranking[0].indeterminate);
  EXPECT_EQ(ranking[1].label(), "R2.Tz");
  EXPECT_NEAR(ranking[1].relative, 0.3, 1e-12);
  EXPECT_TRUE(ranking[1].kept);
  EXPECT_EQ(ranking[2].label(), "R3.Fz");
  EXPECT_NEAR(ranking[2].relative, 0.05, 1e-12);
  EXPECT_FALSE(ranking[2].kept);
  EXPECT_FALSE(ranking[2].indeterminate);
  EXPECT_EQ(ranking[2].node_id, 21);
  // By rms the constant torque leads: 30 against 100 / sqrt(3) = 57.7 N.
  const std::vector<RankedComponent> by_rms = rank_reactions(model, reactions, {true, false}, RankBy::kRms, 0.1);
  EXPECT_EQ(by_rms[0].label(), "R2.Fx");
  EXPECT_NEAR(by_rms[1].relative, 30.0 / (100.0 / std::sqrt(3.0)), 1e-12);
}

}  // namespace
}  // namespace limber::select
