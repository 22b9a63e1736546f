// The seed's set-up (0.2 m crank at 20 rev/s from the start, undamped, no gravity) against a
// geometrically nonlinear, unreduced model of the same rod (corotational_rod.h): the linear
// modal rod (cases/slider_crank_seed_setup.yaml) overshoots it, the stiffened one
// (cases/slider_crank_seed_setup_stiffened.yaml, geometric_stiffening: true) follows it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_error.h"
#include "corotational_rod.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "run/run_driver.h"

namespace limber::run {
namespace {

constexpr double kTEnd = 0.3;                              // [s], as docs/benchmarks.md
constexpr double kSample = 1e-3;                           // [s]

// The case's mid-span deflection in the plane (body z) at every sample.
std::vector<double> limber_deflection(const std::string& case_name) {
  const io::Case input = io::read_case_file(std::string(LIMBER_CASES_DIR) + "/" + case_name);
  const io::Mechanism built =
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  io::RunSettings settings = built.run;
  settings.t_end = kTEnd;
  settings.sample_interval = kSample;
  const int rod = built.model.find_body("rod") - 1;  // results index: ground is not recorded
  std::vector<double> deflection;
  RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample&, const results::Sample& record) {
    deflection.push_back(record.bodies[rod].deflection.z());
  };
  const RunSummary summary = run_mechanism(built.model, built.assembly, settings, hooks);
  EXPECT_TRUE(summary.ok) << case_name << ": " << summary.message;
  return deflection;
}

double peak(const std::vector<double>& x) {
  double m = 0.0;
  for (double v : x) m = std::max(m, std::abs(v));
  return m;
}

TEST(SeedSetupReference, StiffenedModalRodFollowsTheCorotationalBeamTheLinearOneDoesNot) {
  const std::vector<double> reference =
      test::corotational_midspan_deflection(test::seed_setup_rod(50, 2e-5), kTEnd, kSample);
  const std::vector<double> finer =
      test::corotational_midspan_deflection(test::seed_setup_rod(100, 1e-5), kTEnd, kSample);
  const std::vector<double> stiffened = limber_deflection("slider_crank_seed_setup_stiffened.yaml");
  const std::vector<double> linear = limber_deflection("slider_crank_seed_setup.yaml");
  ASSERT_EQ(reference.size(), stiffened.size());
  std::printf("  peaks [mm]: corotational %.2f (finer %.2f), stiffened %.2f, linear %.2f\n",
              1e3 * peak(reference), 1e3 * peak(finer), 1e3 * peak(stiffened), 1e3 * peak(linear));
  std::printf("  rms difference to corotational: finer %.3f, stiffened %.3f, linear %.3f\n",
              bench::relative_rms_error(finer, reference), bench::relative_rms_error(stiffened, reference),
              bench::relative_rms_error(linear, reference));
  // The reference is converged: twice the elements at half the step differ by 0.2 % rms
  // (measured; peaks 38.50 and 38.51 mm). Bound 1 %, a twentieth of the stiffened rod's gap.
  EXPECT_LT(bench::relative_rms_error(finer, reference), 1e-2);
  // Measured: stiffened peak 38.29 mm, 0.55 % under the nonlinear beam's 38.50 mm (37.92 mm,
  // 1.5 % under, when the loads were solved in every evaluation; a peer tool's unreduced
  // nonlinear FE rod: 39 mm); the linear modal rod 61.81 mm, 61 % over.
  // Bounds: 3 % (twice the gap: first order in the loads, 5 modes) and 40 %.
  EXPECT_NEAR(peak(stiffened), peak(reference), 0.03 * peak(reference));
  EXPECT_GT(peak(linear), 1.4 * peak(reference));
  // Over the whole history: 19.4 % rms for the stiffened rod (18.6 % with the loads solved in
  // every evaluation; the undamped ringing drifts in
  // phase: 5 modes against 150 DOFs), 98 % for the linear one, whose history has no likeness
  // to the reference after the first 10 ms. Bounds 30 % and 80 %.
  EXPECT_LT(bench::relative_rms_error(stiffened, reference), 0.3);
  EXPECT_GT(bench::relative_rms_error(linear, reference), 0.8);
}

}  // namespace
}  // namespace limber::run
