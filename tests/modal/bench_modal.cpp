// Benchmark of the modal analysis: a square steel plate, 1 m x 1 m x 0.01 m, meshed with
// n x n flat shell quads (MITC4), either clamped along its edge x = 0 (cantilever, the
// default) or free (6 rigid-body modes found and set aside). One plate per process, so
// the peak resident set size (getrusage) belongs to that plate alone. Prints the wall
// time of mesh, assembly and the whole compute_component_modes (normal modes,
// orthonormalisation, invariants), the peak RSS, and the frequencies with Leissa's
// parameter omega a^2 sqrt(rho h / D); with --split, afterwards, a second eigen-solution
// alone for its factorisation / Lanczos split (not counted in the peak RSS printed above).
// With --ccx-deck FILE it also writes the same model as a CalculiX deck (S4 shells, same
// nodes, element order and clamped edge, *FREQUENCY) for scripts/bench-modal.sh.
//
// Usage: limber_bench_modal [--free] [--modes M] [--split [--tol T] [--ncv K]]
//                           [--ccx-deck FILE] [n]
//        (defaults: cantilever, 10 modes, n = 100, i.e. 61 206 DOFs)
//
//   y
//   ^  +-----------+      n x n quads, ids row by row (x fastest) from 1;
//   |  |#          |      '#': edge x = 0, every DOF held (cantilever).
//   |  |#          |
//   o--+-----------+--> x   (steel E 206.8 GPa, nu 0.3, 7820 kg/m^3)
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "fe/assembly.h"
#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "modal/blas_threads.h"
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

// User CPU time of this process so far [s].
double user_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec) + 1e-6 * usage.ru_utime.tv_usec;
}

constexpr double kThickness = 0.01;
const limber::fe::Material kSteel{"steel", 206.8e9, 0.3, 7820.0};

struct Options {
  int n = 100;
  int modes = 10;
  bool clamped = true;
  bool split = false;
  limber::modal::EigenSolverOptions solver;  // --tol, --ncv: for the --split solution
  std::string ccx_deck;
};

limber::fe::FeModel plate(const Options& options) {
  limber::fe::FeModelBuilder builder;
  limber::fe::RectangularPlateMesh mesh;
  mesh.elements_x = options.n;
  mesh.elements_y = options.n;
  mesh.property = builder.add_shell_property({"plate", kSteel, kThickness});
  const std::vector<int> nodes = limber::fe::add_rectangular_plate(builder, mesh);
  if (options.clamped) {
    for (int j = 0; j <= options.n; ++j) {
      for (int d = 0; d < limber::fe::kDofsPerNode; ++d) {
        builder.fix(nodes[static_cast<std::size_t>(j * (options.n + 1))],
                    static_cast<limber::fe::Dof>(d));
      }
    }
  }
  return std::move(builder).build();
}

// The same plate for CalculiX: S4 (ccx expands it to 3-D solids, unlike MITC4), the same
// node ids, element order and clamped nodes, the lowest `modes` eigenfrequencies.
void write_ccx_deck(const limber::fe::FeModel& model, const Options& options) {
  std::FILE* out = std::fopen(options.ccx_deck.c_str(), "w");
  if (!out) {
    fmt::print(stderr, "cannot write {}\n", options.ccx_deck);
    std::exit(1);
  }
  fmt::print(out, "** limber_bench_modal: {0} x {0} plate, {1}\n*NODE, NSET=NALL\n", options.n,
             options.clamped ? "clamped at x = 0" : "free");
  for (int i = 0; i < model.node_count(); ++i) {
    const Eigen::Vector3d& x = model.node_positions[static_cast<std::size_t>(i)];
    fmt::print(out, "{}, {:.17g}, {:.17g}, {:.17g}\n", model.node_ids[static_cast<std::size_t>(i)],
               x.x(), x.y(), x.z());
  }
  fmt::print(out, "*ELEMENT, TYPE=S4, ELSET=EPLATE\n");
  for (std::size_t e = 0; e < model.shells.size(); ++e) {
    const auto& q = model.shells[e].nodes;
    fmt::print(out, "{}, {}, {}, {}, {}\n", e + 1, model.node_ids[static_cast<std::size_t>(q[0])],
               model.node_ids[static_cast<std::size_t>(q[1])],
               model.node_ids[static_cast<std::size_t>(q[2])],
               model.node_ids[static_cast<std::size_t>(q[3])]);
  }
  fmt::print(out, "*MATERIAL, NAME=STEEL\n*ELASTIC\n{:.17g}, {:.17g}\n*DENSITY\n{:.17g}\n",
             kSteel.youngs_modulus, kSteel.poisson_ratio, kSteel.density);
  fmt::print(out, "*SHELL SECTION, ELSET=EPLATE, MATERIAL=STEEL\n{:.17g}\n", kThickness);
  if (options.clamped) {
    fmt::print(out, "*NSET, NSET=CLAMPED\n");
    for (int j = 0; j <= options.n; ++j) fmt::print(out, "{}\n", 1 + j * (options.n + 1));
    fmt::print(out, "*BOUNDARY\nCLAMPED, 1, 6\n");
  }
  // A free plate has 6 zero eigenvalues: ask for them as well.
  fmt::print(out, "*STEP\n*FREQUENCY\n{}\n*END STEP\n",
             options.modes + (options.clamped ? 0 : 6));
  std::fclose(out);
}

void run(const Options& options) {
  fmt::print("== {0} plate {1} x {1} quads, {2} modes\n",
             options.clamped ? "cantilever" : "free", options.n, options.modes);
  Clock::time_point start = Clock::now();
  const limber::fe::FeModel model = plate(options);
  const double mesh_s = seconds_since(start);
  if (!options.ccx_deck.empty()) write_ccx_deck(model, options);
  start = Clock::now();
  const limber::fe::StructuralMatrices matrices = limber::fe::assemble(model);
  const double assembly_s = seconds_since(start);
  fmt::print("DOFs {} ({} fixed), nonzeros K {}\n", model.dof_count(), model.fixed_dofs.size(),
             matrices.stiffness.nonZeros());
  fmt::print("mesh            {:8.3f} s\nassembly        {:8.3f} s\n", mesh_s, assembly_s);

  // The whole pipeline: normal modes, orthonormalisation, invariants.
  limber::modal::ModeRequest request;
  request.normal_count = options.modes;
  start = Clock::now();
  const limber::modal::ModalResult result =
      limber::modal::compute_component_modes(model, matrices, request);
  fmt::print("component modes {:8.3f} s, status {}\n", seconds_since(start),
             limber::modal::to_string(result.status));
  fmt::print("peak RSS        {:8.1f} MiB\nuser CPU        {:8.3f} s\n", peak_rss_mib(),
             user_cpu_seconds());

  const double d = kSteel.youngs_modulus * std::pow(kThickness, 3) /
                   (12.0 * (1.0 - kSteel.poisson_ratio * kSteel.poisson_ratio));
  const double to_leissa = std::sqrt(kSteel.density * kThickness / d);
  for (std::size_t i = 0; i < result.mode_set.modes.size(); ++i) {
    const double f = result.mode_set.modes[i].frequency_hz;
    fmt::print("  mode {:2d}  {:18.10f} Hz   omega a^2 sqrt(rho h / D) = {:9.4f}\n", i + 1, f,
               2.0 * std::numbers::pi * f * to_leissa);
  }

  if (options.split) {
    const std::vector<int> free = limber::fe::free_dofs(model);
    const limber::modal::EigenSolution solution = limber::modal::solve_lowest_eigenpairs(
        matrices.stiffness, matrices.mass, free, options.modes + (options.clamped ? 0 : 6),
        options.solver);
    // Each frequency also from the Rayleigh quotient of its vector (error quadratic in the
    // vector's), as a check of the eigenvalue returned.
    for (Eigen::Index i = 0; i < solution.eigenvalues.size(); ++i) {
      Eigen::VectorXd phi = Eigen::VectorXd::Zero(model.dof_count());
      for (std::size_t r = 0; r < free.size(); ++r) {
        phi[free[r]] = solution.vectors(static_cast<Eigen::Index>(r), i);
      }
      const double quotient =
          phi.dot(matrices.stiffness * phi) / phi.dot(matrices.mass * phi);
      fmt::print("  split mode {:2d}  {:18.10f} Hz   Rayleigh quotient {:18.10f} Hz\n", i + 1,
                 limber::modal::frequency_hz(solution.eigenvalues[i]),
                 limber::modal::frequency_hz(quotient));
    }
    fmt::print(
        "split: factorisation {:.3f} s, Lanczos {:.3f} s ({} operator applications), backward "
        "error {:.1e}\n",
        solution.factorisation_seconds, solution.lanczos_seconds,
        solution.operator_applications, solution.max_backward_error);
  }
}

}  // namespace

int main(int argc, char** argv) {
  // As limber's main: one BLAS thread (modal/blas_threads.h), so the figures compare.
  limber::modal::use_single_threaded_blas();
  Options options;
  for (int i = 1; i < argc; ++i) {
    const char* arg = argv[i];
    if (!std::strcmp(arg, "--free")) {
      options.clamped = false;
    } else if (!std::strcmp(arg, "--split")) {
      options.split = true;
    } else if (!std::strcmp(arg, "--modes") && i + 1 < argc) {
      options.modes = std::atoi(argv[++i]);
    } else if (!std::strcmp(arg, "--tol") && i + 1 < argc) {
      options.solver.tolerance = std::atof(argv[++i]);
    } else if (!std::strcmp(arg, "--ncv") && i + 1 < argc) {
      options.solver.basis_size = std::atoi(argv[++i]);
    } else if (!std::strcmp(arg, "--ccx-deck") && i + 1 < argc) {
      options.ccx_deck = argv[++i];
    } else if (arg[0] != '-' && std::atoi(arg) > 0) {
      options.n = std::atoi(arg);
    } else {
      fmt::print(stderr,
                 "usage: limber_bench_modal [--free] [--modes M] [--split [--tol T] [--ncv K]] "
                 "[--ccx-deck FILE] [n]\n");
      return 1;
    }
  }
  if (options.modes < 1) {
    fmt::print(stderr, "limber_bench_modal: expected --modes >= 1\n");
    return 1;
  }
  run(options);
  return 0;
}
