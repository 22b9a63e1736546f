// limber_bench_seed_setup: speed at equal accuracy on the seed's set-up as other tools run it
// (cases/slider_crank_seed_setup.yaml: 0.2 m crank at 20 rev/s from t = 0, 5 free-free modes,
// undamped, no gravity), 1 s, samples every 1 ms, through the run driver as `limber run` runs it
// (assembly, redundancy, integration, reactions, energies, and results.h5 written into a
// temporary directory unless --no-file). Error: rms over the samples of the rod's mid-span
// in-plane deflection against a reference run (generalized-α, h = 10 µs, the scheme's own
// converged answer), relative to the reference's rms deflection. Wall time: the run driver's,
// minimum over the repetitions; CPU time: the process's over the same run (less sensitive to
// other jobs on the machine), minimum over the repetitions.
// Not a test: prints a table for docs/benchmarks.md.
//
//   limber_bench_seed_setup [--reps N] [--no-file] [galpha:H[:NEWTON_TOL] ...] [ida:RTOL[:ATOL[:MAX_ORDER]] ...]
//   (default: galpha:1e-3 galpha:5e-4 galpha:2e-4 ida:1e-4 ida:1e-5 ida:1e-6 ida:1e-7 ida:1e-8;
//    IDA's atol is rtol / 100 and its BDF order at most 2 (as `limber run` sets it with flexible
//    bodies) unless given; IDA with the structured Newton matrix, as the case sets it)
#include <fmt/format.h>
#include <unistd.h>

#include <time.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bench_error.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "modal/blas_threads.h"
#include "results/results_writer.h"
#include "run/run_driver.h"

namespace {

using namespace limber;

struct Outcome {
  run::RunSummary summary;
  double wall = 0.0;  // minimum over the repetitions [s]
  double cpu = 0.0;   // process CPU time, minimum over the repetitions [s]
  std::vector<double> deflection;
};

double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

Outcome run_once(const io::Mechanism& mechanism, const integrate::IntegratorOptions& options,
                 int repetitions, bool write_file) {
  io::RunSettings settings = mechanism.run;
  settings.integrator = options;
  settings.t_end = 1.0;
  settings.sample_interval = 1e-3;
  const int rod = mechanism.model.find_body("rod") - 1;  // results index (no ground)
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / fmt::format("limber_bench_seed_{}", getpid());
  Outcome best;
  for (int r = 0; r < repetitions; ++r) {
    Outcome outcome;
    run::RunHooks hooks;
    std::unique_ptr<results::ResultsWriter> writer;
    if (write_file) {
      writer = std::make_unique<results::ResultsWriter>(directory, "bench", "slider_crank_seed_setup.yaml");
      hooks.writer = writer.get();
    }
    hooks.on_sample = [&](const integrate::Sample&, const results::Sample& record) {
      outcome.deflection.push_back(record.bodies[rod].deflection.z());
    };
    const double cpu_start = cpu_seconds();
    outcome.summary = run::run_mechanism(mechanism.model, mechanism.assembly, settings, hooks);
    outcome.wall = outcome.summary.wall_seconds;
    outcome.cpu = cpu_seconds() - cpu_start;
    const double cpu = r == 0 ? outcome.cpu : std::min(best.cpu, outcome.cpu);
    if (r == 0 || outcome.wall < best.wall) best = std::move(outcome);
    best.cpu = cpu;
  }
  std::filesystem::remove_all(directory);
  return best;
}

double relative_rms_error(const Outcome& outcome, const Outcome& reference) {
  return run::bench::relative_rms_error(outcome.deflection, reference.deflection);
}

void print_row(const char* method, const std::string& setting, const Outcome& outcome,
               const Outcome& reference) {
  const integrate::Statistics& s = outcome.summary.statistics;
  if (!outcome.summary.ok) {
    fmt::print("| {} | {} | failed: {} | | | | | | | |\n", method, setting, outcome.summary.message);
    return;
  }
  fmt::print("| {} | {} | {:.0f} | {:.0f} | {} | {} | {} | {} | {} | {:.2f} % |\n", method, setting,
             1e3 * outcome.wall, 1e3 * outcome.cpu, s.steps, s.rejected_steps, s.newton_iterations,
             s.jacobian_evaluations, s.residual_evaluations,
             100 * relative_rms_error(outcome, reference));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  // As limber's main: one BLAS thread (modal/blas_threads.h), so the figures compare.
  limber::modal::use_single_threaded_blas();
  int repetitions = 3;
  bool write_file = true;
  std::vector<std::string> settings;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--reps" && k + 1 < argc) {
      repetitions = std::max(1, std::stoi(argv[++k]));
    } else if (arg == "--no-file") {
      write_file = false;
    } else if (arg.rfind("galpha:", 0) == 0 || arg.rfind("ida:", 0) == 0) {
      settings.push_back(arg);
    } else {
      fmt::print(stderr, "usage: {} [--reps N] [--no-file] [galpha:H[:NEWTON_TOL] ...] [ida:RTOL[:ATOL[:MAX_ORDER]] ...]\n", argv[0]);
      return 1;
    }
  }
  if (settings.empty()) {
    settings = {"galpha:1e-3", "galpha:5e-4", "galpha:2e-4", "ida:1e-4",
                "ida:1e-5",    "ida:1e-6",    "ida:1e-7",    "ida:1e-8"};
  }

  const io::Case input =
      io::read_case_file(std::string(LIMBER_CASES_DIR) + "/slider_crank_seed_setup.yaml");
  const io::Mechanism mechanism =
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));

  // Reference: generalized-α at h = 10 µs (no file: its output cost is not measured).
  const Outcome reference =
      run_once(mechanism, integrate::IntegratorOptions::generalized_alpha(1e-5, 0.8), 1, false);
  if (!reference.summary.ok) {
    fmt::print("reference run failed: {}\n", reference.summary.message);
    return 2;
  }
  fmt::print("reference gen-alpha h = 10 us: rms mid-span deflection {:.3e} m, {:.1f} s; "
             "runs {} results.h5, min of {}\n\n",
             run::bench::rms(reference.deflection), reference.wall, write_file ? "write" : "do not write",
             repetitions);

  fmt::print("| integrator | setting | wall [ms] | CPU [ms] | steps | rejected | Newton iterations | "
             "Jacobians | residuals | deflection error (rms, rel.) |\n"
             "|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& setting : settings) {
    const double value = std::stod(setting.substr(setting.find(':') + 1));
    if (setting.rfind("ida:", 0) == 0) {
      // ida:RTOL[:ATOL[:MAX_ORDER]] (atol rtol / 100 and BDF order ≤ 2 unless given)
      integrate::IntegratorOptions options = integrate::IntegratorOptions::ida(value, value / 100);
      options.max_order = 2;
      options.ida_newton_matrix = integrate::IdaNewtonMatrix::kStructured;
      if (const std::size_t colon = setting.find(':', 4); colon != std::string::npos) {
        options.atol = std::stod(setting.substr(colon + 1));
        if (const std::size_t order = setting.find(':', colon + 1); order != std::string::npos) {
          options.max_order = std::stoi(setting.substr(order + 1));
        }
      }
      print_row(fmt::format("IDA (BDF ≤ {})", options.max_order).c_str(),
                fmt::format("rtol {:.0e}, atol {:.0e}", value, options.atol),
                run_once(mechanism, options, repetitions, write_file), reference);
    } else {
      // galpha:H[:NEWTON_TOLERANCE]
      integrate::IntegratorOptions options = integrate::IntegratorOptions::generalized_alpha(value, 0.8);
      std::string label = fmt::format("h {:.1e}, ρ∞ 0.8", value);
      if (const std::size_t colon = setting.find(':', 7); colon != std::string::npos) {
        options.newton_tolerance = std::stod(setting.substr(colon + 1));
        label += fmt::format(", Newton tolerance {:.0e}", options.newton_tolerance);
      }
      print_row("gen-α", label, run_once(mechanism, options, repetitions, write_file), reference);
    }
  }
  return 0;
}
