// Bricard's line-symmetric 6R linkage (issue 31; tests/run/data/bricard_line_symmetric.yaml):
// one loop of six revolutes whose Gruebler count is 0, yet it moves with one degree of freedom.
// The redundancy analysis must find that freedom, and both integrators must carry the driven
// loop through a full cycle on its line-symmetric motion (bricard_linkage.h). The settings
// table over IDA rtol 1e-4 ... 1e-10 and generalized-α h 1e-3 ... 1e-5 is
// limber_bench_singular_family's (docs/integrators.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include <Eigen/SVD>

#include "bricard_linkage.h"
#include "multibody/multibody_system.h"
#include "parallelogram_chain.h"
#include "run/prepared_start.h"

namespace limber::run {
namespace {

using test::BricardRun;
using test::run_bricard;

// 30 revolute equations on 30 velocities: rank 29, one redundant, so one degree of freedom
// where Gruebler counts none; with the driver's row the loop is held (rank 30 of 31).
TEST(BricardLinkage, RedundancyAnalysisFindsOneDegreeOfFreedom) {
  const std::string path = test::test_case_path(test::kBricardStem);
  const io::Mechanism free = test::build_case_text(test::edited_case(path, "\ndrivers:\n", "\n#drivers:\n#"), path);
  ASSERT_TRUE(free.model.drivers.empty());
  const PreparedStart released = prepare_start(free.model, free.assembly);
  EXPECT_EQ(free.model.nv, 30);
  EXPECT_EQ(free.model.num_equations(), 30);
  EXPECT_EQ(released.partition.independent.size(), 29u);  // mobility 30 - 29 = 1
  ASSERT_EQ(released.redundant.size(), 1u);

  const io::Mechanism driven = test::build_test_case(test::kBricardStem);
  const PreparedStart held = prepare_start(driven.model, driven.assembly);
  EXPECT_EQ(driven.model.num_equations(), 31);
  EXPECT_EQ(held.partition.independent.size(), 30u);  // mobility 0: the driver holds the loop
  EXPECT_EQ(held.redundant.size(), 1u);
  EXPECT_TRUE(held.lost_at_singular_start.empty());
}

// One cycle (1 s, J2 a full turn): IDA at rtol 1e-8 against generalized-α at h = 1e-4.
// Bounds against the measured values printed, with room for IDA's error control at rtol 1e-8
// over lengths of 0.3 m (~1e-8): the symmetry (closed form) and the driver's angle 1e-7 rad
// (measured 1.6e-9 and 1e-11 rad with IDA, 1e-14 with generalized-α), closure 1e-7 m
// (2.5e-9 m), the two methods' body origins 1e-7 m apart (2.4e-9 m).
TEST(BricardLinkage, BothIntegratorsCarryItThroughACycleOnItsLineSymmetricMotion) {
  const BricardRun ida = run_bricard(integrate::Method::kIda, 1e-8, 1.0);
  const BricardRun galpha = run_bricard(integrate::Method::kGeneralizedAlpha, 1e-4, 1.0);
  for (const BricardRun* r : {&ida, &galpha}) {
    const RunSummary& s = r->summary;
    std::printf("  %s: %s, symmetry %.2e rad, driver %.2e rad, closure %.2e m, energy %.2e, %ld steps\n",
                s.integrator.c_str(), s.ok ? "ok" : s.message.c_str(), r->max_symmetry_error,
                r->max_driver_error, s.max_position_violation, s.accuracy.energy_relative, s.statistics.steps);
    ASSERT_TRUE(s.ok) << s.message;
    EXPECT_NEAR(s.t_reached, 1.0, 1e-12);
    EXPECT_LT(r->max_symmetry_error, 1e-7) << s.integrator;
    EXPECT_LT(r->max_driver_error, 1e-7) << s.integrator;
    EXPECT_LT(s.max_position_violation, 1e-7) << s.integrator;
    EXPECT_TRUE(s.accurate()) << s.integrator;
    EXPECT_TRUE(s.singular_passages.empty()) << s.singular_passages.front().message();
  }
  // Second method: every body origin of one run against the other's at each sample.
  ASSERT_EQ(ida.q.size(), galpha.q.size());
  const io::Mechanism built = test::build_test_case(test::kBricardStem);
  double apart = 0.0;
  for (std::size_t k = 0; k < ida.q.size(); ++k) {
    for (std::size_t b = 1; b < built.model.bodies.size(); ++b) {
      const int at = built.model.bodies[b].q_offset;
      apart = std::max(apart, (ida.q[k].segment<3>(at) - galpha.q[k].segment<3>(at)).norm());
    }
  }
  std::printf("  body origins apart: %.2e m\n", apart);
  EXPECT_LT(apart, 1e-7);
}

// IDA at its tightest settings in the table, rtol 1e-10 with atol 1e-12: before λ's Newton
// weight was loosened on a corrector failure (ida_integrator.cpp, kLambdaRelaxation) the
// linkage failed at t = 0 and the simple parallelogram at t = 8e-6 s, both with h ~ 1e-13 s.
// 0.1 s each, required accurate (the linkage's energy balance measured 5e-10 of the scale).
TEST(BricardLinkage, IdaStartsAtRtol1e10WithAtol1e12) {
  for (const std::string stem : {std::string(test::kBricardStem), test::parallelogram_chain_stem(1)}) {
    const io::Mechanism built = test::build_test_case(stem);
    io::RunSettings settings = test::settings_at(built, integrate::Method::kIda, 1e-10, 0.1);
    settings.integrator.atol = 1e-12;
    const RunSummary s = run_mechanism(built.model, built.assembly, settings);
    ASSERT_TRUE(s.ok) << stem << ": " << s.message;
    EXPECT_NEAR(s.t_reached, 0.1, 1e-12) << stem;
    EXPECT_TRUE(s.accurate()) << stem;
    EXPECT_LT(s.max_position_violation, 1e-7) << stem;
  }
}

// IDA at rtol 1e-10 with atol 1e-12 past t = 0.214 s, where the rows IDA holds lose rank
// (their smallest singular value falls to 2e-3 of its start value) while the 31 equations keep
// rank 30: other rows hold there. IDA's corrector fails 2 ms before it, and the failure was
// taken for a singular configuration and stepped over (a 10 ms Taylor step: the symmetry still
// 4e-12 rad, but the energy balance 1.2e-3 of the scale from the integrals across the stretch).
// Now the system reselects its rows there and IDA restarts on them (singular_step_over.h).
// Bounds against the closed form with room for IDA's error control at rtol 1e-10 over 0.3 m
// lengths: symmetry and driver angle 1e-9 rad (measured 4.2e-12), energy balance 1e-7 of the
// scale (measured 1.8e-9; the step-over's 1.2e-3 is far above), no passage.
TEST(BricardLinkage, IdaAtRtol1e10ReselectsRowsWhereTheHeldOnesLoseRank) {
  const BricardRun r = run_bricard(integrate::Method::kIda, 1e-10, 0.5, {}, 1e-12);
  const RunSummary& s = r.summary;
  std::printf("  ida: %s, symmetry %.2e rad, driver %.2e rad, energy %.2e, %ld steps, %ld rejected\n",
              s.ok ? "ok" : s.message.c_str(), r.max_symmetry_error, r.max_driver_error, s.accuracy.energy_relative,
              s.statistics.steps, s.statistics.rejected_steps);
  ASSERT_TRUE(s.ok) << s.message;
  EXPECT_NEAR(s.t_reached, 0.5, 1e-12);
  EXPECT_LT(r.max_symmetry_error, 1e-9);
  EXPECT_LT(r.max_driver_error, 1e-9);
  EXPECT_LT(s.accuracy.energy_relative, 1e-7);
  EXPECT_TRUE(s.accurate());
  EXPECT_TRUE(s.singular_passages.empty()) << s.singular_passages.front().message();
}

// Smallest singular value of the unit rows of G (integrate/singular_step_over.h's margin).
double unit_rows_margin(Eigen::MatrixXd G) {
  for (Eigen::Index k = 0; k < G.rows(); ++k) G.row(k).normalize();
  return Eigen::JacobiSVD<Eigen::MatrixXd>(G).singularValues().minCoeff();
}

// The singular step-over's probe asks MultibodySystem::reselection_candidate, which must change
// nothing (issue 31): at the sample of 0.19-0.23 s where the rows held from the start are worst
// conditioned (above: other rows hold there) it answers that re-selection would switch, twice
// the same, with the G of the rows it would choose, and the rows held stay until
// reselect_constraints switches to exactly those: their G then, bit for bit (the same rows of
// the same evaluation), better conditioned than the rows left.
TEST(BricardLinkage, ReselectionCandidateAsksWithoutChangingTheRows) {
  const io::Mechanism built = test::build_test_case(test::kBricardStem);
  const PreparedStart start = prepare_start(built.model, built.assembly);
  multibody::MultibodySystem system(built.model, start.partition);
  const BricardRun run = run_bricard(integrate::Method::kGeneralizedAlpha, 1e-4, 0.23);
  std::size_t worst = 0;
  double worst_margin = 1.0;
  Eigen::MatrixXd G;
  for (std::size_t k = 0; k < run.t.size(); ++k) {
    if (run.t[k] < 0.19) continue;
    system.constraint_jacobian_v(run.t[k], run.q[k], G);
    if (const double margin = unit_rows_margin(G); margin < worst_margin) {
      worst_margin = margin;
      worst = k;
    }
  }
  const double t = run.t[worst];
  const Eigen::VectorXd& q = run.q[worst];
  std::printf("  held rows' margin %.2e at t = %.4f s\n", worst_margin, t);

  // At the start: nothing to switch (this call sets the pivot the held rows are judged by).
  Eigen::MatrixXd G_candidate, G_again, G_held;
  EXPECT_FALSE(system.reselection_candidate(0.0, start.state.q, G_candidate));
  EXPECT_FALSE(system.reselect_constraints(0.0, start.state.q));
  const std::vector<int> held = system.partition().independent;
  ASSERT_TRUE(system.reselection_candidate(t, q, G_candidate));
  ASSERT_TRUE(system.reselection_candidate(t, q, G_again));
  EXPECT_EQ(system.partition().independent, held);
  ASSERT_EQ(G_again.rows(), G_candidate.rows());
  EXPECT_EQ((G_again - G_candidate).cwiseAbs().maxCoeff(), 0.0);

  ASSERT_TRUE(system.reselect_constraints(t, q));
  EXPECT_NE(system.partition().independent, held);
  system.constraint_jacobian_v(t, q, G_held);
  ASSERT_EQ(G_held.rows(), G_candidate.rows());
  EXPECT_EQ((G_held - G_candidate).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(unit_rows_margin(G_held), 2.0 * worst_margin);
}

}  // namespace
}  // namespace limber::run
