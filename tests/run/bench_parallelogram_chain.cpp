// limber_bench_parallelogram_chain: chains of N = 1, 2, 3 parallelograms sharing their cranks
// (issue 31), 10 s at 2 rev/s (40 singular passages), with IDA at rtol 1e-4 … 1e-10 (atol
// rtol/100, at least 1e-10) and generalized-α at h = 1e-3 … 1e-5, through the run driver (no file): end and largest
// coupler error against the closed form (parallelogram_chain.h), steps, rejected steps,
// singular passages reported, energy estimate, wall. Not a test: prints the table of
// docs/integrators.md. Arguments (optional): N, "ida"/"galpha", a setting, t_end — one row.
#include <fmt/format.h>

#include <cstdlib>
#include <string>

#include "parallelogram_chain.h"

namespace {

using namespace limber;

void row(int n, integrate::Method method, double setting, double t_end) {
  const test::ChainRun r = test::run_parallelogram_chain(n, method, setting, t_end);
  const run::RunSummary& s = r.summary;
  fmt::print("| {} | {} {:g} | {} | {:.2g} | {:.2g} | {} | {} | {} | {:.1e} | {:.1f} |{}\n", n,
             integrate::to_string(method), setting, s.ok ? "ok" : fmt::format("failed at {:.4g} s", s.t_reached),
             r.end_error, r.max_error, s.statistics.steps, s.statistics.rejected_steps,
             s.singular_passages.size(), s.accuracy.energy_relative, s.wall_seconds,
             s.ok ? "" : " " + s.message);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5) {
    const auto method = std::string(argv[2]) == "ida" ? integrate::Method::kIda : integrate::Method::kGeneralizedAlpha;
    row(std::atoi(argv[1]), method, std::atof(argv[3]), std::atof(argv[4]));
    return 0;
  }
  fmt::print("| N | integrator | status | end error [m] | max error [m] | steps | rejected | passages | energy | wall [s] |\n");
  fmt::print("|---|---|---|---|---|---|---|---|---|---|\n");
  // Generalized-α's cost grows with 1/h (100 000 steps of the 2-chain took 6 min on a loaded
  // machine): h = 1e-4 over 2 s (8 passages), 1e-5 over 0.3 s (one).
  for (int n = 1; n <= 3; ++n) {
    for (const double rtol : {1e-4, 1e-6, 1e-8, 1e-10}) row(n, integrate::Method::kIda, rtol, 10.0);
    row(n, integrate::Method::kGeneralizedAlpha, 1e-3, 10.0);
    row(n, integrate::Method::kGeneralizedAlpha, 1e-4, 2.0);
    row(n, integrate::Method::kGeneralizedAlpha, 1e-5, 0.3);
  }
}
