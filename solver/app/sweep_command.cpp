// `limber sweep`: runs a case over a grid of settings (integrator, IDA tolerance or
// generalized-α step, modes per flexible body), each point as its own `limber run` child
// process, measures each against a reference and writes the work-precision table
// (docs/sweep.md). Under MPI the points are shared among the ranks; rank 0 gathers the rows and
// writes the table.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/command.h"
#include "app/stop_signal.h"
#include "app/sweep_ranks.h"
#include "sweep/sweep_study.h"
#include "sweep/work_precision.h"
#include "results/file_names.h"

namespace limber::app {

namespace {

struct SweepOptions {
  std::string case_file;
  std::string output_dir;
  std::vector<std::string> over;
  std::string reference = "tight";
  std::optional<double> target;
  std::string norm = "rms";
  std::vector<std::string> quantities;
  int jobs = 0;  // 0: the number of cores
  bool fresh = false;
  bool json = false;
  std::optional<double> t_end, atol, max_wall;
};

std::string percent(double fraction) {
  return std::isfinite(fraction) ? fmt::format("{:.3g} %", 100.0 * fraction) : std::string("-");
}

void print_table(std::FILE* out, const std::vector<sweep::SweepRow>& rows, std::optional<std::size_t> chosen) {
  fmt::print(out, "\n  {:<28} {:<13} {:>8} {:>7} {:>5} {:>7} {:>6} {:>7} {:>10} {:>10}  {}\n", "point", "status",
             "wall [s]", "steps", "rej", "newton", "jac", "MiB", "rms error", "peak error", "");
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const sweep::SweepRow& r = rows[k];
    std::string note = chosen && *chosen == k ? "chosen" : "";
    if (r.resumed) note += note.empty() ? "resumed" : ", resumed";
    if (!r.finished() && !r.message.empty()) note += (note.empty() ? "" : "; ") + r.message;
    if (!r.resolved()) {
      note += fmt::format("{}not resolved: {:.1f} steps per period at f_max {:.0f} Hz ({} needed)", note.empty() ? "" : "; ",
                          r.steps_per_period, r.f_max_hz, select::kStepsPerPeriod);
    }
    const std::string wall = std::isfinite(r.wall_s) ? fmt::format("{:.3f}", r.wall_s) : "-";
    const std::string memory = std::isfinite(r.peak_rss_mib) ? fmt::format("{:.1f}", r.peak_rss_mib) : "-";
    fmt::print(out, "  {:<28} {:<13} {:>8} {:>7} {:>5} {:>7} {:>6} {:>7} {:>10} {:>10}  {}\n", r.point.name(),
               r.status, wall, r.steps, r.rejected_steps, r.newton_iterations, r.jacobian_evaluations,
               memory, percent(r.error_rms), percent(r.error_peak), note);
  }
}

// The ranks of the MPI job (one without MPI) as the library's RankGroup.
class CommandRanks : public sweep::RankGroup {
 public:
  int rank() const override { return ranks_.rank(); }
  int size() const override { return ranks_.size(); }
  int broadcast(int value) const override { return ranks_.broadcast(value); }
  std::vector<int> max_over_ranks(const std::vector<int>& values) const override {
    return ranks_.max_over_ranks(values);
  }
  std::vector<std::string> gather_to_lead(const std::string& text) const override {
    return ranks_.gather_to_lead(text);
  }

 private:
  SweepRanks ranks_;
};

int sweep_case(const SweepOptions& options) {
  const CommandRanks ranks;
  sweep::SweepRequest request;
  request.case_file = options.case_file;
  request.root = options.output_dir.empty()
                     ? std::filesystem::path("out") /
                           (std::filesystem::path(options.case_file).stem().string() + "_sweep")
                     : std::filesystem::path(options.output_dir);
  request.over = options.over;
  request.reference = options.reference;
  request.target = options.target;
  request.rms = options.norm == "rms";
  request.quantities = options.quantities;
  request.jobs = options.jobs;
  request.fresh = options.fresh;
  request.t_end = options.t_end;
  request.atol = options.atol;
  request.max_wall = options.max_wall;
  request.executable = std::filesystem::read_symlink("/proc/self/exe");

  std::FILE* text = options.json ? stderr : stdout;
  const StopSignals stop_signals;
  // Each child single-threaded: OpenBLAS (pthread build) and OpenMP would otherwise start a thread
  // per core in every child (the modal reduction); a value the user set is kept.
  setenv("OPENBLAS_NUM_THREADS", "1", 0);
  setenv("OMP_NUM_THREADS", "1", 0);
  sweep::SweepHooks hooks;
  hooks.text = [text](const std::string& line) {
    fmt::print(text, "{}", line);
    std::fflush(text);
  };
  hooks.log = [](const std::string& line) { fmt::print(stderr, "{}", line); };
  hooks.should_stop = [] { return StopSignals::received() != 0; };
  const sweep::SweepOutcome outcome = sweep::run_sweep(request, ranks, hooks);
  if (outcome.interrupted_in_reference) {
    if (outcome.lead) fmt::print(stderr, "limber: sweep interrupted during the reference run\n");
    return kExitInterrupted;
  }
  if (!outcome.lead) return outcome.interrupted ? kExitInterrupted : kExitOk;

  fmt::print(text, "\nerrors against the reference ({}), largest over {} quantities (default: every joint reaction "
                   "and deflection component at least 1 % of the largest of its kind):",
             outcome.reference_label, outcome.quantities.size());
  print_table(text, outcome.rows, outcome.chosen);
  if (options.target) {
    if (outcome.chosen) {
      const sweep::SweepRow& row = outcome.rows[*outcome.chosen];
      fmt::print(text, "\ncheapest setting with {} error <= {:g} ({}): {} ({:.3f} s, {} error {}); run it with:\n  {}\n",
                 options.norm, *options.target, percent(*options.target), row.point.name(), row.wall_s, options.norm,
                 percent(row.error(request.rms)), sweep::run_command_line(request, row.point));
    } else {
      fmt::print(stderr, "limber: warning: no point meets the target {:g} ({} error) with its own accuracy check "
                         "passed; see the table\n", *options.target, options.norm);
    }
  }
  fmt::print(text, "wrote {}\n", (request.root / results::kSweepFolder).string());
  if (options.json) fmt::print(stdout, "{}\n", outcome.document);
  if (outcome.interrupted) {
    fmt::print(stderr, "limber: sweep interrupted; finished points are kept and a rerun resumes ({})\n",
               (request.root / results::kRunsFolder).string());
    return kExitInterrupted;
  }
  return kExitOk;
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* cli = app.add_subcommand(
      "sweep", "Speed against accuracy over a grid of settings, against a reference");
  cli->footer(
      "Each grid point is its own 'limber run' child process (single-threaded; --jobs at a time)\n"
      "writing DIR/runs/<point>/{results.h5,run.json,run.log,process.json}. Per point: the run's\n"
      "wall time, steps, rejected steps, Newton iterations, Jacobian and residual evaluations, peak\n"
      "memory (the child's), its own accuracy check (status ok or ok_inaccurate) and, against the\n"
      "reference, the peak and rms relative error of each compared quantity on the reference's\n"
      "samples (default: every determinate joint reaction component, joint frame, and\n"
      "deflection-probe axis whose peak is at least 1 % of the largest of its kind, reactions\n"
      "above 1e-6 of the largest; --quantities names others). Writes DIR/sweep/work_precision.csv\n"
      "and .json, DIR/sweep/errors.csv (per quantity) and DIR/results.h5 (the reference's), so that\n"
      "'limber report DIR' plots error against wall time. A failed or crashed point is a row with\n"
      "its message. Rerunning the same command resumes: points whose results.h5 is finished are\n"
      "not rerun (--fresh reruns all). Under 'mpirun -n N limber sweep ...' the points are shared\n"
      "among the ranks (DIR on a filesystem all ranks see: rank 0 makes the reference), each rank\n"
      "measures its points, and rank 0 gathers the rows and writes the table.\n"
      "The case comes before --over (which takes every word up to the next option).\n"
      "Axes (--over, docs/sweep.md): integrator (default ida,galpha), rtol (IDA; default\n"
      "1e-3,1e-4,1e-5,1e-6), step (generalized-alpha; default 4,2,1,1/2 x the case's), modes\n"
      "(normal modes per flexible body; default 1/2,1,2 x the case's), e.g.\n"
      "  limber sweep case.yaml --over integrator,rtol,step,modes\n"
      "  limber sweep case.yaml --over integrator=galpha step=1e-3,5e-4,2.5e-4 modes=3,5 --target 0.01\n"
      "Reference 'tight': the grid's most modes with generalized-alpha at 1/8 of its smallest step\n"
      "(IDA at 1/100 of its smallest rtol when the grid has no generalized-alpha point), run once\n"
      "into DIR/reference/<point> and reused on resume. Reference 'nonlinear': the case with\n"
      "every flexible body nonlinear (limber run --formulation nonlinear), generalized-alpha at the\n"
      "smaller of the case's and the grid's smallest step: the errors are then what the modal\n"
      "model costs against the geometrically exact rod (beams only, undamped).\n"
      "Exit codes: 0 done (failed points are rows), 1 bad input, 2 the reference run failed or\n"
      "its own accuracy check did not pass (status ok_inaccurate),\n"
      "3 internal error, 4 interrupted by SIGINT or SIGTERM (finished points kept; rerun resumes).");
  cli->add_option("case", options->case_file, "Case file (YAML, docs/case-format.md)")->required();
  cli->add_option("--over", options->over,
                  "Axes: names (integrator,rtol,step,modes: default values) or axis=v1,v2,... (several allowed)")
      ->required()
      ->expected(1, -1);
  cli->add_option("-o,--output", options->output_dir, "Output directory (default: out/<case file stem>_sweep)");
  cli->add_option("--reference", options->reference, "'tight' (one much tighter run), 'nonlinear' (the case with every flexible body nonlinear: "
                  "what the modal model costs; docs/nonlinear-beams.md) or a finished results.h5")
      ->capture_default_str();
  cli->add_option("--target", options->target,
                  "Error target as a fraction (0.01 = 1 %): print the cheapest point that meets it");
  cli->add_option("--norm", options->norm, "Error measure for --target: rms or peak (relative)")
      ->check(CLI::IsMember({"peak", "rms"}))
      ->capture_default_str();
  cli->add_option("--quantities", options->quantities,
                  "Quantities to compare, comma-separated, e.g. \"R3 force x,rod deflection z\" (names as in "
                  "DIR/sweep/errors.csv, unit optional)")
      ->delimiter(',');
  cli->add_option("-j,--jobs", options->jobs, "Runs at a time (per MPI rank; 0: the number of cores)")
      ->capture_default_str();
  cli->add_flag("--fresh", options->fresh, "Rerun every point and the reference, even those finished before");
  cli->add_option("--t-end", options->t_end, "End time of every run [s] (>= 0; default: the case's)");
  cli->add_option("--atol", options->atol, "IDA absolute tolerance of every IDA run (default: the case's)");
  cli->add_option("--max-wall", options->max_wall,
                  "Wall-clock budget of each point's run [s] (not the reference's): a point not finished by then "
                  "fails as a row");
  cli->add_flag("--json", options->json,
                "Print one JSON object on stdout: {\"status\", \"case\", \"reference\": {\"label\", \"results\"}, "
                "\"quantities\", \"norm\", \"target\", \"target_met\", \"chosen\", \"run_options\", \"points\": "
                "[{\"point\", \"curve\", \"integrator\", \"rtol\", \"step\", \"modes\", \"status\", \"message\", "
                "\"exit_code\", \"wall_s\", \"process_s\", \"steps\", \"rejected_steps\", \"newton_iterations\", "
                "\"jacobian_evaluations\", \"residual_evaluations\", \"peak_rss_mib\", \"energy_relative\", "
                "\"local_error\", \"drift_relative\", \"error_peak\", \"error_rms\", \"worst_quantity\", "
                "\"errors\": [{\"quantity\", \"peak\", \"rms\"}], \"resumed\", \"rank\", \"chosen\"}], "
                "\"directory\"} (also DIR/sweep/work_precision.json); the text goes to stderr");
  return {cli, [options] { return sweep_case(*options); }};
}

}  // namespace limber::app
