// Parallelograms through their singular positions (issue 14): every crank along the ground
// line at t = 0.125, 0.375, 0.625 s (tests/run/data/*parallelogram.yaml). The double
// parallelogram is redundant and cannot leave its branch; the simple one could fold into the
// anti-parallelogram there. Closed form on the parallelogram branch: the coupler translates,
// its rotation is 0. Bound 1e-6 rad: IDA at rtol 1e-6 measures 9e-8, generalized-alpha at
// h = 1 ms 2e-14 (its positions solve g = 0 to Newton's tolerance); the anti-parallelogram
// turns the coupler by up to pi, so any branch switch is 6 orders above the bound.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../results/h5_test_read.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "multibody/constraints.h"
#include "results/results_writer.h"
#include "run/prepared_start.h"
#include "run/run_driver.h"
#include "run/singular_passage.h"
#include "run_test_support.h"

namespace limber::run {
namespace {

const std::string kDouble = std::string(LIMBER_TEST_DATA_DIR) + "/double_parallelogram.yaml";
const std::string kSimple = std::string(LIMBER_TEST_DATA_DIR) + "/parallelogram.yaml";

struct Trace {
  RunSummary summary;
  std::vector<double> t, coupler_rotation, violation;
  std::vector<std::string> warnings;
  std::vector<multibody::State> states;  // every sample's (t, q, v)
  std::filesystem::path directory;       // holds the run's results.h5
};

Trace run_case(const std::string& path, integrate::Method method, double step_or_rtol) {
  const io::Case input = io::read_case_text(test::read_text(path), path);
  const io::Mechanism built =
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  io::RunSettings settings = built.run;
  settings.integrator.method = method;
  if (method == integrate::Method::kIda) {
    settings.integrator.rtol = step_or_rtol;
    settings.integrator.atol = step_or_rtol * 1e-2;
  } else {
    settings.integrator.step = step_or_rtol;
  }
  settings.integrator.max_wall_seconds = 30.0;
  const multibody::Model& model = built.model;
  const int coupler = model.bodies[model.find_body("coupler")].q_offset;
  Trace trace;
  RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample& record) {
    const Eigen::Vector4d p = sample.q.segment<4>(coupler + 3).normalized();
    trace.t.push_back(sample.t);
    trace.states.push_back({sample.t, sample.q, sample.v});
    trace.coupler_rotation.push_back(2.0 * std::atan2(p.tail<3>().norm(), std::abs(p(0))));
    trace.violation.push_back(record.position_violation);
  };
  hooks.on_warning = [&](const std::string& w) { trace.warnings.push_back(w); };
  trace.directory = test::fresh_directory(std::string("parallelogram_") + integrate::to_string(method));
  {
    results::ResultsWriter writer(trace.directory, "parallelogram", path);
    hooks.writer = &writer;
    trace.summary = run_mechanism(model, built.assembly, settings, hooks);
  }
  const RunSummary& s = trace.summary;
  double rot = 0.0, viol = 0.0;
  for (size_t k = 0; k < trace.t.size(); ++k) {
    rot = std::max(rot, trace.coupler_rotation[k]);
    viol = std::max(viol, trace.violation[k]);
  }
  std::printf("  %s %s: %s t %.4g s, %d samples, max coupler rotation %.3e rad, max violation %.3e, "
              "%ld steps %.2f s %s\n",
              path.substr(path.rfind('/') + 1).c_str(), integrate::to_string(method),
              s.ok ? "ok" : "FAILED", s.t_reached, s.samples, rot, viol, s.statistics.steps,
              s.wall_seconds, s.message.c_str());
  for (const std::string& w : trace.warnings) std::printf("    warning: %s\n", w.c_str());
  return trace;
}

constexpr double kRotationBound = 1e-6;  // [rad]
constexpr double kViolationBound = 1e-6; // [m or rad]

void expect_parallelogram_branch(const Trace& trace) {
  ASSERT_TRUE(trace.summary.ok) << trace.summary.message;
  EXPECT_NEAR(trace.summary.t_reached, 0.7, 1e-12);
  EXPECT_EQ(trace.t.size(), 701u);
  for (size_t k = 0; k < trace.t.size(); ++k) {
    ASSERT_LT(trace.coupler_rotation[k], kRotationBound) << "t = " << trace.t[k];
    ASSERT_LT(trace.violation[k], kViolationBound) << "t = " << trace.t[k];
  }
}

// Before issue 14's fix generalized-alpha failed at t = 0.124 s: its step grid lands on the
// singular configuration at t = 0.125 s ("the iteration matrix of a step h = 0.001 s is
// singular"); it now stretches that step past the singular instant.
TEST(Parallelogram, DoubleRunsThroughItsSingularPositionsWithBothIntegrators) {
  expect_parallelogram_branch(run_case(kDouble, integrate::Method::kIda, 1e-6));
  expect_parallelogram_branch(run_case(kDouble, integrate::Method::kGeneralizedAlpha, 1e-3));
}

// Every singular position is reported (run/singular_passage.h), once, at the sample where
// the links are collinear (the samples fall on them), naming the loop's joints; the run goes
// on, status unchanged (accurate).
void expect_singular_passages_reported(const Trace& trace, const std::vector<std::string>& joints) {
  const std::vector<SingularPassage>& passages = trace.summary.singular_passages;
  ASSERT_EQ(passages.size(), 3u);
  ASSERT_EQ(trace.warnings.size(), 3u);
  const double expected[] = {0.125, 0.375, 0.625};
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(passages[k].t, expected[k], 1e-9);
    EXPECT_LT(passages[k].ratio, 1e-4);  // measured 2e-7 to 8e-7: the Gram matrix's rounding floor
    for (const std::string& joint : joints) {
      EXPECT_NE(std::find(passages[k].names.begin(), passages[k].names.end(), joint),
                passages[k].names.end()) << joint << " at t = " << passages[k].t;
    }
    EXPECT_NE(trace.warnings[k].find("lose rank at t = "), std::string::npos) << trace.warnings[k];
    // Branch check: velocities continuous across the passage (the prediction's own error is
    // (ω Δt)² ~ 1e-3 here; a change of branch jumps by O(1)).
    EXPECT_GE(passages[k].velocity_jump, 0.0);
    EXPECT_LT(passages[k].velocity_jump, 1e-2);
    EXPECT_NE(trace.warnings[k].find("stayed on the branch it arrived on"), std::string::npos);
  }
  EXPECT_TRUE(trace.summary.accurate());
  // results.h5 holds the same passages.
  const hid_t file = H5Fopen((trace.directory / results::kResultsFileName).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const std::vector<double> time = results::testing::read_doubles(file, "/constraints/singular_passages/time");
  const std::vector<double> ratio = results::testing::read_doubles(file, "/constraints/singular_passages/ratio");
  const std::vector<std::string> names = test::read_fixed_strings(file, "/constraints/singular_passages/joints");
  const std::vector<double> jump = results::testing::read_doubles(file, "/constraints/singular_passages/velocity_jump");
  H5Fclose(file);
  ASSERT_EQ(time.size(), 3u);
  ASSERT_EQ(names.size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(time[k], passages[k].t);
    EXPECT_EQ(ratio[k], passages[k].ratio);
    EXPECT_EQ(jump[k], passages[k].velocity_jump);
    EXPECT_NE(names[k].find(passages[k].names.front()), std::string::npos) << names[k];
  }
}

TEST(Parallelogram, DoubleReportsItsSingularPositions) {
  // R1 is not required: at t = 0.375 s with IDA its rows fall just under the tenth of the
  // singular vector's largest entry that names a joint.
  const std::vector<std::string> joints{"R2", "R3", "R4", "R5", "R6"};
  expect_singular_passages_reported(run_case(kDouble, integrate::Method::kIda, 1e-6), joints);
  expect_singular_passages_reported(run_case(kDouble, integrate::Method::kGeneralizedAlpha, 1e-3), joints);
}

// The simple parallelogram could fold into the anti-parallelogram at each singular position;
// both integrators report the passage and stay on the parallelogram branch (asserted: a
// silent switch fails the coupler's rotation bound).
TEST(Parallelogram, SimpleReportsItsSingularPositionsAndStaysOnTheParallelogramBranch) {
  const std::vector<std::string> joints{"R1", "R2", "R3", "R4"};
  for (const auto& [method, x] : {std::pair{integrate::Method::kIda, 1e-6},
                                 std::pair{integrate::Method::kGeneralizedAlpha, 1e-3}}) {
    const Trace trace = run_case(kSimple, method, x);
    expect_parallelogram_branch(trace);
    expect_singular_passages_reported(trace, joints);
  }
}

// The branch check sees a change of branch: the simple parallelogram's recorded motion, with
// crank2's angular velocity reversed after the first passage (as on the anti-parallelogram,
// where the cranks turn opposite ways), jumps by 2 of the frame speeds (crank2's rate, the
// largest, turns from +ω to −ω); the unaltered record stays below 1e-2.
TEST(Parallelogram, BranchCheckReportsAVelocityJumpAcrossAPassage) {
  const Trace trace = run_case(kSimple, integrate::Method::kGeneralizedAlpha, 1e-3);
  ASSERT_TRUE(trace.summary.ok);
  const io::Case input = io::read_case_text(test::read_text(kSimple), kSimple);
  const io::Mechanism built =
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const multibody::Model& model = built.model;
  const int crank2 = model.bodies[model.find_body("crank2")].v_offset;
  const int rank = static_cast<int>(prepare_start(model, built.assembly).partition.independent.size());
  SingularPassageMonitor monitor(model, rank);
  multibody::Workspace ws(model);
  std::vector<SingularPassage> passages;
  for (multibody::State state : trace.states) {
    if (state.t > 0.125 && state.t < 0.25) state.v.segment<3>(crank2 + 3) *= -1.0;
    multibody::evaluate_constraints(model, state, multibody::Stage::kPosition, ws);
    if (monitor.add(state, ws.G)) passages.push_back(monitor.last());
  }
  ASSERT_GE(passages.size(), 1u);
  EXPECT_TRUE(passages[0].changed_branch());
  EXPECT_NEAR(passages[0].velocity_jump, 2.0, 0.02);  // 2 up to the prediction's 1e-3
  EXPECT_EQ(passages[0].jump_body, "crank2");
  EXPECT_NE(passages[0].message().find("CHANGED BRANCH"), std::string::npos);
}

// Assembled at the singular configuration, the loop's in-plane equation that only the
// singularity makes dependent is named and the run refuses to start (it went on and came apart
// by 19 % of the mechanism's size before). The regular starts above pass the same check.
TEST(Parallelogram, RefusesToStartAtItsSingularConfiguration) {
  const std::string path = std::string(LIMBER_TEST_DATA_DIR) + "/parallelogram_singular_start.yaml";
  for (const auto method : {integrate::Method::kIda, integrate::Method::kGeneralizedAlpha}) {
    const Trace trace = run_case(path, method, method == integrate::Method::kIda ? 1e-6 : 1e-3);
    EXPECT_FALSE(trace.summary.ok);
    EXPECT_EQ(trace.summary.failure, "singular start");
    EXPECT_EQ(trace.summary.samples, 0);
    EXPECT_NE(trace.summary.message.find("singular configuration: equation(s) R"), std::string::npos)
        << trace.summary.message;
  }
  for (const std::string& regular : {kSimple, kDouble}) {
    const io::Case input = io::read_case_text(test::read_text(regular), regular);
    const io::Mechanism built =
        io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
    EXPECT_TRUE(prepare_start(built.model, built.assembly).lost_at_singular_start.empty()) << regular;
  }
}

}  // namespace
}  // namespace limber::run
