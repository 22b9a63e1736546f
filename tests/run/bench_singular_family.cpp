// limber_bench_singular_family: issue 31's family of mechanisms through their singular or
// overconstrained positions, with IDA at rtol 1e-4 … 1e-10 (atol rtol/100, at least 1e-10) and
// generalized-α at h = 1e-3 … 1e-5, through the run driver (no file):
//   chainN   N = 1, 2, 3 parallelograms sharing their cranks, 2 rev/s (parallelogram_chain.h):
//            coupler origin error [m] against the closed form;
//   bricard  Bricard's line-symmetric 6R linkage, J2 at 1 rev/s (bricard_linkage.h): the
//            line symmetry's error |theta_{k+3} - theta_k| [rad];
//   five_bar the planar five-bar through its stretched configuration, 1 rev/s (five_bar.h):
//            P's error [m] against the closed form.
// Per row: status, end and largest error, steps, rejected steps, singular passages reported,
// the run's energy-balance estimate, wall. Not a test: prints the table of docs/integrators.md.
// Arguments (optional): a mechanism, "ida"/"galpha", a setting, t_end[, IDA's atol] — one row;
// a mechanism alone — its rows.
#include <fmt/format.h>

#include <cstdlib>
#include <string>

#include "bricard_linkage.h"
#include "five_bar.h"
#include "parallelogram_chain.h"

namespace {

using namespace limber;

struct Row {
  run::RunSummary summary;
  double end_error = 0.0, max_error = 0.0;
};

Row run_row(const std::string& mechanism, integrate::Method method, double setting, double t_end, double atol) {
  if (mechanism == "bricard") {
    const test::BricardRun r = test::run_bricard(method, setting, t_end, {}, atol);
    return {r.summary, r.end_symmetry_error, r.max_symmetry_error};
  }
  if (mechanism == "five_bar") {
    const test::FiveBarRun r = test::run_five_bar(method, setting, t_end);
    return {r.summary, r.end_error, r.max_error};
  }
  const test::ChainRun r = test::run_parallelogram_chain(std::atoi(mechanism.c_str() + 5), method, setting, t_end);
  return {r.summary, r.end_error, r.max_error};
}

// atol: IDA's, when positive, instead of the table's rule (singular_family.h; Bricard only).
void row(const std::string& mechanism, integrate::Method method, double setting, double t_end, double atol = 0.0) {
  const Row r = run_row(mechanism, method, setting, t_end, atol);
  const run::RunSummary& s = r.summary;
  fmt::print("| {} | {} {:g}{} | {:g} s | {} | {:.2g} | {:.2g} | {} | {} | {} | {:.1e} | {:.1f} |{}\n", mechanism,
             integrate::to_string(method), setting, atol > 0.0 ? fmt::format(", atol {:g}", atol) : "", t_end,
             s.ok ? "ok" : fmt::format("failed at {:.4g} s", s.t_reached), r.end_error, r.max_error,
             s.statistics.steps, s.statistics.rejected_steps, s.singular_passages.size(),
             s.accuracy.energy_relative, s.wall_seconds, s.ok ? "" : " " + s.message);
  std::fflush(stdout);
}

// Every setting on one mechanism. Generalized-α's cost grows with 1/h (100 000 steps of the
// 2-chain took 6 min on a loaded machine): h = 1e-4 over a fifth of the span, 1e-5 over
// `short_span` (a passage or a cycle's part).
void rows(const std::string& mechanism, double span, double short_span) {
  for (const double rtol : {1e-4, 1e-6, 1e-8, 1e-10}) row(mechanism, integrate::Method::kIda, rtol, span);
  row(mechanism, integrate::Method::kGeneralizedAlpha, 1e-3, span);
  row(mechanism, integrate::Method::kGeneralizedAlpha, 1e-4, 0.2 * span);
  row(mechanism, integrate::Method::kGeneralizedAlpha, 1e-5, short_span);
}

void all_rows(const std::string& mechanism) {
  if (mechanism == "bricard") {
    // Also at IDA's tightest atol, where a corrector failure with no rank loss near was once
    // taken for a singular configuration (singular_step_over.h).
    rows(mechanism, 3.0, 0.3);
    return row(mechanism, integrate::Method::kIda, 1e-10, 3.0, 1e-12);
  }
  if (mechanism == "five_bar") return rows(mechanism, 4.0, 0.6);
  rows(mechanism, 10.0, 0.3);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5 || argc == 6) {
    const auto method = std::string(argv[2]) == "ida" ? integrate::Method::kIda : integrate::Method::kGeneralizedAlpha;
    row(argv[1], method, std::atof(argv[3]), std::atof(argv[4]), argc == 6 ? std::atof(argv[5]) : 0.0);
    return 0;
  }
  fmt::print("| mechanism | integrator, setting | span | status | end error | largest error | steps | rejected | passages | energy | wall [s] |\n");
  fmt::print("|---|---|---|---|---|---|---|---|---|---|---|\n");
  if (argc == 2) {
    all_rows(argv[1]);
    return 0;
  }
  for (const char* mechanism : {"chain1", "chain2", "chain3", "bricard", "five_bar"}) all_rows(mechanism);
}
