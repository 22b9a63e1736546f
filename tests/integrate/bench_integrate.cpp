// limber_bench_integrate: error against cost of both integrators on the Cartesian pendulum.
//
//   limber_bench_integrate            (prints a Markdown table)
//
// Pendulum m = 1 kg, L = 1 m, g = 9.81 m/s², released at rest from θ0 = 1 rad, 5 s (about
// 2.5 periods), samples every 10 ms. The reference is IDA at rtol = atol = 1e-12; "error q" and
// "error λ" are the largest differences over the samples. Wall time is the best of 5 runs.
#include <algorithm>
#include <cstdio>
#include <vector>

#include "integrate/simulate.h"
#include "test_systems.h"

namespace {

using limber::integrate::IntegratorOptions;
using limber::integrate::Sample;
using limber::integrate::SimulationResult;
using limber::integrate::testing::CartesianPendulum;

constexpr double kTheta0 = 1.0, kEnd = 5.0, kSampleInterval = 0.01;
constexpr int kRepeats = 5;

struct Run {
  SimulationResult result;
  std::vector<Sample> samples;
};

Run run(CartesianPendulum& pendulum, const IntegratorOptions& options,
        const std::vector<double>& times) {
  const limber::integrate::InitialState start{0.0, pendulum.position(kTheta0),
                                              Eigen::VectorXd::Zero(2)};
  Run best;
  for (int repeat = 0; repeat < kRepeats; ++repeat) {
    Run current;
    current.samples.reserve(times.size());
    current.result = simulate(pendulum, options, start, times,
                              [&](const Sample& s) { current.samples.push_back(s); });
    if (repeat == 0 || current.result.wall_seconds < best.result.wall_seconds) best = current;
  }
  return best;
}

void print_row(const char* integrator, const char* setting, const Run& r, const Run& reference) {
  double error_q = 0.0, error_lambda = 0.0;
  for (size_t i = 0; i < r.samples.size(); ++i) {
    error_q = std::max(error_q, (r.samples[i].q - reference.samples[i].q).lpNorm<Eigen::Infinity>());
    error_lambda = std::max(error_lambda,
                            std::abs(r.samples[i].lambda(0) - reference.samples[i].lambda(0)));
  }
  const auto& s = r.result.statistics;
  std::printf("| %-6s | %-12s | %8.2f | %6ld | %5ld | %7ld | %5ld | %7ld | %9.2e | %9.2e | %s |\n",
              integrator, setting, 1e3 * r.result.wall_seconds, s.steps, s.rejected_steps,
              s.newton_iterations, s.jacobian_evaluations, s.residual_evaluations, error_q,
              error_lambda, limber::integrate::to_string(r.result.status.code));
}

}  // namespace

int main() {
  CartesianPendulum pendulum(1.0, 1.0, 9.81);
  const auto times = limber::integrate::uniform_sample_times(0.0, kEnd, kSampleInterval);
  const Run reference = run(pendulum, IntegratorOptions::ida(1e-12, 1e-12), times);

  std::printf("| integrator | setting | wall [ms] | steps | rejected | Newton it. | Jacobians | "
              "residuals | error q [m] | error λ [N/m] | status |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  char setting[32];
  for (const double tol : {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10}) {
    std::snprintf(setting, sizeof setting, "tol %.0e", tol);
    print_row("IDA", setting, run(pendulum, IntegratorOptions::ida(tol, tol), times), reference);
  }
  for (const double h : {1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4}) {
    std::snprintf(setting, sizeof setting, "h %.0e", h);
    print_row("galpha", setting,
              run(pendulum, IntegratorOptions::generalized_alpha(h, 0.8), times), reference);
  }
  return 0;
}
