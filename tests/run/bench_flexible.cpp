// limber_bench_flexible: error against cost of both integrators on the seed's slider-crank with
// its flexible rod (cases/slider_crank.yaml: 5 free-free modes, 0.05 m crank, spin-up over
// 0.1 s to 20 rev/s), 1 s, samples every 1 ms, through the run driver (assembly, redundancy,
// integration, reactions, energies per sample; no file). Error: rms over the samples of the
// rod's mid-span deflection (in-plane) against a reference run (generalized-α, h = 10 µs),
// relative to the reference's rms deflection. Wall time: best of 3.
// Not a test: prints a table for docs/benchmarks.md.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "bench_error.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "modal/blas_threads.h"
#include "run/run_driver.h"

namespace {

using namespace limber;

struct Outcome {
  run::RunSummary summary;
  double wall = 0.0;  // best of the repetitions [s]
  std::vector<double> deflection;
};

Outcome run_once(const io::Mechanism& mechanism, const integrate::IntegratorOptions& options,
                 int repetitions) {
  io::RunSettings settings = mechanism.run;
  settings.integrator = options;
  settings.t_end = 1.0;
  settings.sample_interval = 1e-3;
  const int rod = mechanism.model.find_body("rod") - 1;  // results index (no ground)
  Outcome best;
  for (int r = 0; r < repetitions; ++r) {
    Outcome outcome;
    run::RunHooks hooks;
    hooks.on_sample = [&](const integrate::Sample&, const results::Sample& record) {
      outcome.deflection.push_back(record.bodies[rod].deflection.z());
    };
    outcome.summary = run::run_mechanism(mechanism.model, mechanism.assembly, settings, hooks);
    outcome.wall = outcome.summary.wall_seconds;
    if (r == 0 || outcome.wall < best.wall) best = std::move(outcome);
  }
  return best;
}

double relative_rms_error(const Outcome& outcome, const Outcome& reference) {
  return run::bench::relative_rms_error(outcome.deflection, reference.deflection);
}

void print_row(const char* method, const std::string& setting, const Outcome& outcome,
               const Outcome& reference) {
  const integrate::Statistics& s = outcome.summary.statistics;
  if (!outcome.summary.ok) {
    fmt::print("| {} | {} | failed: {} | | | |\n", method, setting, outcome.summary.message);
    return;
  }
  fmt::print("| {} | {} | {:.0f} | {} | {} | {:.1e} |\n", method, setting, 1e3 * outcome.wall,
             s.steps, s.rejected_steps, relative_rms_error(outcome, reference));
}

}  // namespace

int main() {
  // As limber's main: one BLAS thread (modal/blas_threads.h), so the figures compare.
  limber::modal::use_single_threaded_blas();
  const io::Case input = io::read_case_file(std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml");
  const io::Mechanism mechanism = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));

  // Reference: generalized-α at h = 10 µs, checked against IDA at rtol 1e-6.
  const Outcome reference =
      run_once(mechanism, integrate::IntegratorOptions::generalized_alpha(1e-5, 0.8), 1);
  const Outcome check = run_once(mechanism, integrate::IntegratorOptions::ida(1e-6, 1e-8), 1);
  if (!reference.summary.ok || !check.summary.ok) {
    fmt::print("reference run failed: {} {}\n", reference.summary.message, check.summary.message);
    return 2;
  }
  fmt::print("reference gen-alpha h = 10 us: rms mid-span deflection {:.3e} m, {:.1f} s; IDA rtol "
             "1e-6 against it: {:.1e} rms\n\n",
             run::bench::rms(reference.deflection), reference.wall, relative_rms_error(check, reference));

  fmt::print("| integrator | setting | wall [ms] | steps | rejected | deflection error (rms, rel.) |\n"
             "|---|---|---|---|---|---|\n");
  for (double rtol : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8}) {
    print_row("IDA (BDF ≤ 2)", fmt::format("rtol {:.0e}, atol {:.0e}", rtol, rtol / 100),
              run_once(mechanism, integrate::IntegratorOptions::ida(rtol, rtol / 100), 3), reference);
  }
  for (double h : {2e-3, 1e-3, 6e-4, 5e-4, 2e-4, 1e-4}) {
    print_row("gen-α", fmt::format("h {:.0e}, ρ∞ 0.8", h),
              run_once(mechanism, integrate::IntegratorOptions::generalized_alpha(h, 0.8), 3), reference);
  }
  return 0;
}
