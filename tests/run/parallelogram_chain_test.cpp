// Chains of N = 1, 2, 3 parallelograms sharing their cranks through their singular positions
// (issue 31; tests/run/data/parallelogram_chain_N.yaml): every link collinear at t = 0.125 +
// 0.25 k s, each loop free to fold into its anti-parallelogram there. 0.7 s here (three
// passages) at one setting per integrator; the settings table over 10 s (IDA rtol 1e-4 … 1e-10,
// generalized-α h 1e-3 … 1e-5) is limber_bench_singular_family's (docs/integrators.md).
// Closed form on the parallelogram branch (parallelogram_chain.h); an anti-parallelogram
// moves a coupler by up to 2 a = 0.2 m, so any change of branch is far above the bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "parallelogram_chain.h"

namespace limber::run {
namespace {

using test::ChainRun;
using test::run_parallelogram_chain;

// Every passage reported once, on the branch it arrived on, naming the joints of every loop.
void expect_passages(const ChainRun& r, int n, double t_end) {
  const std::vector<SingularPassage>& passages = r.summary.singular_passages;
  const auto expected = static_cast<std::size_t>((t_end - 0.125) / 0.25) + 1;
  ASSERT_EQ(passages.size(), expected);
  for (std::size_t k = 0; k < passages.size(); ++k) {
    // Samples every 1 ms fall on the singular instants.
    EXPECT_NEAR(passages[k].t, 0.125 + 0.25 * static_cast<double>(k), 1e-9);
    EXPECT_FALSE(passages[k].changed_branch()) << passages[k].message();
    EXPECT_GE(passages[k].velocity_jump, 0.0);
    for (int loop = 0; loop < n; ++loop) {
      for (const std::string joint : {"A" + std::to_string(loop), "B" + std::to_string(loop)}) {
        EXPECT_NE(std::find(passages[k].names.begin(), passages[k].names.end(), joint), passages[k].names.end())
            << joint << " at t = " << passages[k].t;
      }
    }
  }
}

// IDA at rtol 1e-9 (atol 1e-11): before the step-over (integrate/singular_step_over.h) the
// 2-chain stopped at t = 0.1248 s, its corrector failing down to h = 4e-21 s; at rtol 1e-6 it
// stopped at 2.625 s. Bound 1e-6 m: measured 8.5e-11 - 1.4e-10 m (a driven chain has no free
// coordinate: the step-over's projection lands on the closed form); the energy balance measured
// 1.2e-7 - 3.1e-7 of the energy scale, within the accuracy check's bound.
TEST(ParallelogramChain, IdaStepsOverEverySingularPositionOnTheParallelogramBranch) {
  for (int n = 1; n <= 3; ++n) {
    const ChainRun r = run_parallelogram_chain(n, integrate::Method::kIda, 1e-9, 0.7);
    ASSERT_TRUE(r.summary.ok) << "N = " << n << ": " << r.summary.message;
    EXPECT_NEAR(r.summary.t_reached, 0.7, 1e-12);
    EXPECT_LT(r.max_error, 1e-6) << "N = " << n;
    EXPECT_TRUE(r.summary.accurate()) << "N = " << n;
    expect_passages(r, n, 0.7);
  }
}

// Generalized-α at h = 1 ms: its grid lands on the singular instants, which it steps over
// (generalized_alpha.cpp). Bound 1e-6 m: measured 1.1e-8 m (its positions solve g = 0 to
// Newton's tolerance), energy 1.4e-5 of the scale.
TEST(ParallelogramChain, GeneralizedAlphaRunsThroughEverySingularPositionOnTheParallelogramBranch) {
  for (int n = 1; n <= 3; ++n) {
    const ChainRun r = run_parallelogram_chain(n, integrate::Method::kGeneralizedAlpha, 1e-3, 0.7);
    ASSERT_TRUE(r.summary.ok) << "N = " << n << ": " << r.summary.message;
    EXPECT_LT(r.max_error, 1e-6) << "N = " << n;
    EXPECT_TRUE(r.summary.accurate()) << "N = " << n;
    expect_passages(r, n, 0.7);
  }
}

// A run that ends inside the stretch IDA would step over cannot step over it: it stops with a
// message that names the singular configuration and what to change, not IDA's bare
// "corrector convergence failed".
TEST(ParallelogramChain, IdaStopsNamingTheSingularConfigurationItCannotStepOver) {
  const ChainRun r = run_parallelogram_chain(2, integrate::Method::kIda, 1e-9, 0.125);
  ASSERT_FALSE(r.summary.ok);
  EXPECT_NE(r.summary.message.find("at a singular configuration"), std::string::npos) << r.summary.message;
  EXPECT_NE(r.summary.message.find("Remedies:"), std::string::npos) << r.summary.message;
  EXPECT_EQ(r.summary.message.find("IDA failed with flag"), std::string::npos) << r.summary.message;
  EXPECT_LT(r.summary.t_reached, 0.125);
}

}  // namespace
}  // namespace limber::run
