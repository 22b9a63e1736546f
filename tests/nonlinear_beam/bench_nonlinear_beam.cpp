// Wall time of the co-rotational structure's evaluations (not a test; docs/nonlinear-beams.md):
// one f_int + K_t evaluation of a 100-element straight rod in a deformed state, and the static
// solve of a 100-element cantilever under a tip load PL^2/EI = 10 in 10 increments, and 1000
// generalized-alpha steps of the same cantilever under a suddenly applied tip load
// PL^2/EI = 1 (h = 1/100 of its first period, rho_inf = 0.9).
// Usage: limber_bench_nonlinear_beam [elements, default 100]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>

#include "nonlinear_beam/beam_inertia.h"
#include "nonlinear_beam/beam_structure.h"
#include "nonlinear_beam/dynamic_solver.h"
#include "nonlinear_beam/rotation.h"
#include "nonlinear_beam/static_solver.h"
#include "beam_test_support.h"

using namespace limber;

int main(int argc, char** argv) {
  const int elements = argc > 1 ? std::atoi(argv[1]) : 100;

  // A unit cantilever, EI = 1, EA = 1e8 (the elastica tests' rod).
  const nonlinear_beam::test_models::Cantilever cantilever = nonlinear_beam::test_models::unit_cantilever(elements);
  const fe::FeModel& model = cantilever.model;
  const int tip = cantilever.tip;
  const nonlinear_beam::BeamStructure structure = nonlinear_beam::build_beam_structure(model);

  // Evaluations in a bent, twisted state.
  nonlinear_beam::BeamState state = nonlinear_beam::reference_state(structure);
  for (int i = 0; i < structure.node_count(); ++i) {
    const double s = static_cast<double>(i) / elements;
    state.positions[i] += 0.1 * Eigen::Vector3d(-s * s, s * s, 0.2 * s);
    state.rotations[i] = nonlinear_beam::exp_quaternion(Eigen::Vector3d(0.3 * s, -0.2 * s, 0.5 * s));
  }
  nonlinear_beam::BeamWorkspace workspace = nonlinear_beam::make_workspace(structure);
  const int repeats = 2000;
  auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) nonlinear_beam::evaluate_force_and_tangent(structure, state, workspace);
  const double per_evaluation =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / repeats;

  // Static solve.
  nonlinear_beam::StaticOptions options;
  options.load_increments = 10;
  start = std::chrono::steady_clock::now();
  const nonlinear_beam::StaticSolution solution = nonlinear_beam::solve_static(
      structure, {{tip, Eigen::Vector3d(0.0, 10.0, 0.0), Eigen::Vector3d::Zero()}},
      options);
  const double solve = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int iterations = std::accumulate(solution.iterations.begin(), solution.iterations.end(), 0);
  std::printf("%d elements: f_int + K_t %.1f us per evaluation; static solve PL^2/EI = 10: %.1f ms, "
              "%d Newton iterations, status %d, v/L = %.6f\n",
              elements, per_evaluation * 1e6, solve * 1e3, iterations,
              static_cast<int>(solution.status), solution.state.positions[tip].y());

  // Dynamics: 1000 steps from rest under a sudden tip load (rho A = 1, EI = 1: first period
  // 2 pi / 3.516 s).
  const nonlinear_beam::NodalInertia inertia = nonlinear_beam::lumped_inertia(model);
  nonlinear_beam::DynamicOptions dynamic;
  dynamic.step = 2.0 * 3.14159265358979323846 / 3.516 / 100.0;
  dynamic.rho_inf = 0.8;
  dynamic.loads.push_back({tip, Eigen::Vector3d(0.0, 1.0, 0.0), Eigen::Vector3d::Zero()});
  nonlinear_beam::BeamGeneralizedAlpha integrator(structure, inertia, dynamic);
  integrator.init(0.0, nonlinear_beam::reference_state(structure),
                  nonlinear_beam::zero_velocity(structure.node_count()));
  start = std::chrono::steady_clock::now();
  nonlinear_beam::DynamicReport report;
  for (int k = 0; k < 1000 && report.status == nonlinear_beam::DynamicStatus::kOk; ++k) report = integrator.step();
  const double dynamics = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%d elements: 1000 generalized-alpha steps (sudden tip load PL^2/EI = 1): %.1f ms, "
              "%.2f Newton iterations per step, status %d, tip v/L at t = %.3f s: %.6f\n",
              elements, dynamics * 1e3,
              static_cast<double>(integrator.statistics().newton_iterations) /
                  std::max<long>(1, integrator.statistics().steps),
              static_cast<int>(report.status), integrator.time(),
              integrator.state().positions[tip].y());
  return solution.status == nonlinear_beam::StaticStatus::kConverged &&
                 report.status == nonlinear_beam::DynamicStatus::kOk
             ? 0
             : 1;
}
