// Benchmark of the modal analysis: a free (unsupported) square steel plate,
// 1 m x 1 m x 0.01 m, meshed with n x n flat shell quads, its 10 lowest elastic modes
// (6 rigid-body modes found and set aside). Prints the wall time of each stage
// (mesh, assembly, Cholesky factorisation of K - sigma M, ARPACK Lanczos, whole
// compute_component_modes) and the process's peak resident set size (getrusage).
//
// Usage: limber_bench_modal [n ...]     (default: 100 204, i.e. 61k and 252k DOFs)
//
//   y
//   ^  +-----------+      n x n quads, 6 DOFs per node, nothing held:
//   |  |           |      free-free plate, sigma < 0 shift-invert.
//   |  |           |
//   o--+-----------+--> x   (1 m square, 0.01 m thick, steel E 206.8 GPa, nu 0.3, 7820 kg/m^3)
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "fe/assembly.h"
#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "modal/component_modes.h"
#include "modal/normal_modes.h"
#include "modal/sparse_eigensolver.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Peak resident set size of this process so far [MiB].
double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

constexpr double kThickness = 0.01;
const limber::fe::Material kSteel{"steel", 206.8e9, 0.3, 7820.0};

limber::fe::FeModel plate(int n) {
  limber::fe::FeModelBuilder builder;
  limber::fe::RectangularPlateMesh mesh;
  mesh.elements_x = n;
  mesh.elements_y = n;
  mesh.property = builder.add_shell_property({"plate", kSteel, kThickness});
  limber::fe::add_rectangular_plate(builder, mesh);
  return std::move(builder).build();
}

void run(int n) {
  fmt::print("== free plate {0} x {0} quads\n", n);
  // Set-up: mesh and assembly.
  Clock::time_point start = Clock::now();
  const limber::fe::FeModel model = plate(n);
  const double mesh_s = seconds_since(start);
  start = Clock::now();
  const limber::fe::StructuralMatrices matrices = limber::fe::assemble(model);
  const double assembly_s = seconds_since(start);
  fmt::print("DOFs {}, nonzeros K {}\n", model.dof_count(), matrices.stiffness.nonZeros());
  fmt::print("mesh          {:8.3f} s\nassembly      {:8.3f} s\n", mesh_s, assembly_s);

  // Eigen-solution alone: 6 rigid + 10 elastic modes.
  const limber::modal::EigenSolution solution =
      limber::modal::solve_lowest_eigenpairs(matrices.stiffness, matrices.mass, 16);
  if (solution.status != limber::modal::ModalStatus::kOk) {
    fmt::print("eigen-solution failed: {}\n", solution.message);
    return;
  }
  fmt::print("factorisation {:8.3f} s\nARPACK        {:8.3f} s   (backward error {:.1e})\n",
             solution.factorisation_seconds, solution.lanczos_seconds,
             solution.max_backward_error);

  // Frequencies and the Leissa parameter omega a^2 sqrt(rho h / D).
  const double d = kSteel.youngs_modulus * std::pow(kThickness, 3) /
                   (12.0 * (1.0 - kSteel.poisson_ratio * kSteel.poisson_ratio));
  const double to_leissa = std::sqrt(kSteel.density * kThickness / d);
  for (Eigen::Index i = 0; i < solution.eigenvalues.size(); ++i) {
    const double f = limber::modal::frequency_hz(solution.eigenvalues[i]);
    fmt::print("  mode {:2d}  {:12.5f} Hz   omega a^2 sqrt(rho h / D) = {:9.4f}\n", i + 1, f,
               2.0 * std::numbers::pi * f * to_leissa);
  }

  // The whole pipeline: normal modes, orthonormalisation, invariants.
  limber::modal::ModeRequest request;
  request.normal_count = 10;
  start = Clock::now();
  const limber::modal::ModalResult result =
      limber::modal::compute_component_modes(model, matrices, request);
  fmt::print("component modes (10 normal, with invariants) {:8.3f} s, status {}\n",
             seconds_since(start), limber::modal::to_string(result.status));
  fmt::print("peak RSS      {:8.1f} MiB\n\n", peak_rss_mib());
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes;
  for (int i = 1; i < argc; ++i) sizes.push_back(std::atoi(argv[i]));
  if (sizes.empty()) sizes = {100, 204};
  for (int n : sizes) run(n);
  return 0;
}
