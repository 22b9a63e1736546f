// Recovered stresses in a dynamic run (cases/slider_crank.yaml, whose rod records its stresses):
// the rod's mid-span bending moment from the element stiffness (modal stresses superposed at
// each sample) against M = −E Iy w'' from the second difference of the same sample's nodal
// deflections (a second method), and every recorded stress finite.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "run/run_driver.h"

namespace limber::run {
namespace {

TEST(StressRun, SliderCrankRodMidSpanMomentMatchesCurvature) {
  const io::Case input = io::read_case_file(std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml");
  const io::Mechanism built =
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  io::RunSettings settings = built.run;
  settings.t_end = 0.3;  // spin-up and two turns at speed: the case's peak is at 0.11 s
  settings.sample_interval = 1e-3;
  const multibody::Model& model = built.model;
  const multibody::FlexibleBody& rod = *model.bodies[static_cast<std::size_t>(model.find_body("rod"))].flexible;
  ASSERT_TRUE(rod.stress_output.has_value());
  const int record_index = model.find_body("rod") - 1;  // results index: ground is not recorded

  // Rod: 100 elements of h = 0.01 m along body x, nodes 0..100; mid-span node 50 is end 0 of
  // element 50 (history column 50 with `elements: all`). Section 0.01 (y) x 0.02 (z).
  const double h = 0.01, e_modulus = 206.8e9, inertia_y = 0.01 * std::pow(0.02, 3) / 12.0;
  const int mid = 50;
  double worst = 0.0, largest = 0.0, peak = 0.0, peak_time = 0.0, ratio_at_peak = 0.0;
  int recorded = 0;
  bool finite = true;
  RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample&, const results::Sample& record) {
    const results::BodySample& body = record.bodies[static_cast<std::size_t>(record_index)];
    finite = finite && std::isfinite(body.stress_peak);
    if (!body.stress_recorded) return;
    ++recorded;
    finite = finite && body.stress_equivalent.allFinite() && body.stress_beam_resultants.allFinite();
    // Method 1: the recovered My at end 0 of element 50 (resultant 4 of 12).
    const double my = body.stress_beam_resultants(12 * mid + 4);
    // Method 2: −E Iy w'' at node 50 from w = uz of nodes 49, 50, 51 (body z, in the plane).
    const auto w = [&](int node) { return rod.shapes.row(6 * node + 2).dot(body.modal_coordinates); };
    const double curvature = (w(mid - 1) - 2.0 * w(mid) + w(mid + 1)) / (h * h);
    const double my_curvature = -e_modulus * inertia_y * curvature;
    worst = std::max(worst, std::abs(my - my_curvature));
    largest = std::max(largest, std::abs(my));
    if (body.stress_peak > peak) {
      peak = body.stress_peak;
      peak_time = record.time;
      // Against a half-sine deflection δ sin(πx/L) of the chord-relative mid-span deflection:
      // σ ≈ E c π² δ / L² (a rough, shape-dependent estimate, printed only).
      ratio_at_peak = peak / (e_modulus * 0.01 * std::numbers::pi * std::numbers::pi * std::abs(body.deflection.z()));
    }
  };
  const RunSummary summary = run_mechanism(model, built.assembly, settings, hooks);
  ASSERT_TRUE(summary.ok) << summary.message;
  std::printf("slider-crank rod: %d history rows; mid-span My recovered vs -E I w'' max difference %.3e N m "
              "of max |My| %.3e N m (%.2e); peak stress %.4e Pa at t = %.3f s, peak / (E c pi^2 delta / L^2) "
              "= %.3f\n", recorded, worst, largest, worst / largest, peak, peak_time, ratio_at_peak);
  EXPECT_TRUE(finite);
  EXPECT_EQ(recorded, 31);  // samples 0, 10, ..., 300 with `every: 10`
  // The two differ by the element's own fixed-end inertia moment q h²/12 and the difference
  // formula's h² w''''/12, both O((h/L)²) = 1e-4 of the mid-span moment (measured 2.8e-4): 1e-3.
  EXPECT_LT(worst, 1e-3 * largest);
  EXPECT_GT(largest, 1.0);  // the rod bends (tens of N m): the comparison is not of zeros
}

}  // namespace
}  // namespace limber::run
