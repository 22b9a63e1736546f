// `limber sweep`: runs a case over a grid of settings (integrator, IDA tolerance or
// generalized-α step, modes per flexible body), each point as its own `limber run` child
// process, measures each against a reference and writes the work-precision table
// (docs/sweep.md). Under MPI the points are shared among the ranks; rank 0 gathers the rows and
// writes the table.
#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/command.h"
#include "core/json_text.h"
#include "app/stop_signal.h"
#include "app/sweep_ranks.h"
#include "core/error.h"
#include "io/case_reader.h"
#include "results/directory_lock.h"
#include "results/results_writer.h"
#include "sweep/process_pool.h"
#include "sweep/run_series.h"
#include "sweep/sweep_grid.h"
#include "sweep/work_precision.h"
#include "results/file_names.h"
#include "results/results_layout.h"

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

using Clock = std::chrono::steady_clock;

std::string percent(double fraction) {
  return std::isfinite(fraction) ? fmt::format("{:.3g} %", 100.0 * fraction) : std::string("-");
}

// The case's settings the grid's defaults come from.
sweep::CaseDefaults case_defaults(const io::Case& input) {
  sweep::CaseDefaults defaults;
  const integrate::IntegratorOptions& integrator = input.mechanism->run.integrator;
  defaults.method = integrator.method;
  defaults.rtol = integrator.rtol;
  defaults.step = integrator.step;
  for (const io::FlexibleBodyCase& body : input.flexible_bodies) {
    defaults.normal_modes = std::max(defaults.normal_modes, body.request.normal_count);
  }
  return defaults;
}

// The `limber run` command line of a point (the reference runs without --max-wall: it must finish).
std::vector<std::string> run_argv(const SweepOptions& options, const std::string& executable,
                                  const sweep::SweepPoint& point, const std::filesystem::path& directory,
                                  bool reference) {
  std::vector<std::string> argv = {executable, "run", options.case_file, "-o", directory.string(), "--json"};
  for (const std::string& option : point.run_options()) argv.push_back(option);
  if (options.t_end) argv.insert(argv.end(), {"--t-end", fmt::format("{}", *options.t_end)});
  if (options.atol && !point.atol) argv.insert(argv.end(), {"--atol", fmt::format("{}", *options.atol)});
  if (options.max_wall && !reference) argv.insert(argv.end(), {"--max-wall", fmt::format("{}", *options.max_wall)});
  return argv;
}

sweep::ChildJob child_job(const SweepOptions& options, const std::string& executable, const sweep::SweepPoint& point,
                          const std::filesystem::path& directory, bool reference = false) {
  return {run_argv(options, executable, point, directory, reference), directory / results::kRunJsonFileName, directory / results::kRunLogFileName};
}

// The options a user passes to `limber run` for the row's setting.
std::string run_command_line(const SweepOptions& options, const sweep::SweepPoint& point) {
  std::string line = "limber run " + options.case_file;
  for (const std::string& option : point.run_options()) line += " " + option;
  if (options.t_end) line += fmt::format(" --t-end {:g}", *options.t_end);
  return line;
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

int sweep_case(const SweepOptions& options) {
  const SweepRanks ranks;
  const bool lead = ranks.rank() == 0;
  if (options.target && !(*options.target > 0.0)) {
    throw InputError(fmt::format("expected --target > 0 (a fraction, 0.01 = 1 %), got {:g}", *options.target));
  }
  if (options.jobs < 0) {
    throw InputError(fmt::format("expected --jobs >= 1 (0: the number of cores), got {}", options.jobs));
  }
  if (options.t_end && !(*options.t_end >= 0.0)) {
    throw InputError(fmt::format("expected --t-end >= 0, got {:g}", *options.t_end));
  }
  const io::Case input = io::read_case_file(options.case_file);
  if (!input.mechanism) {
    throw InputError("expected a mechanism (a 'bodies' section), got none", SourceLocation{options.case_file, 0, 0});
  }
  const sweep::CaseDefaults defaults = case_defaults(input);
  const std::vector<sweep::SweepPoint> points = sweep::expand_grid(sweep::parse_over(options.over, defaults), defaults);
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int parallel = options.jobs > 0 ? options.jobs : cores;
  const bool rms = options.norm == "rms";

  std::FILE* text = options.json ? stderr : stdout;
  const std::filesystem::path root =
      options.output_dir.empty()
          ? std::filesystem::path("out") / (std::filesystem::path(options.case_file).stem().string() + "_sweep")
          : std::filesystem::path(options.output_dir);
  std::filesystem::create_directories(root);
  std::optional<results::DirectoryLock> lock;
  if (lead) lock.emplace(root);
  const std::string executable = std::filesystem::read_symlink("/proc/self/exe").string();
  if (lead) {
    fmt::print(text, "limber sweep: {} ({}), {} points, {} at a time{}\n", input.title, input.file, points.size(),
               parallel, ranks.size() > 1 ? fmt::format(" on each of {} MPI ranks", ranks.size()) : "");
  }
  const StopSignals stop_signals;
  // Each child single-threaded: OpenBLAS (pthread build) and OpenMP would otherwise start a thread
  // per core in every child (the modal reduction); a value the user set is kept.
  setenv("OPENBLAS_NUM_THREADS", "1", 0);
  setenv("OMP_NUM_THREADS", "1", 0);

  // The reference: one tight run, made once (rank 0) and reused on resume, or a given file.
  std::filesystem::path reference_file;
  std::string reference_label;
  if (options.reference == "tight") {
    const double case_atol = options.atol.value_or(input.mechanism->run.integrator.atol);
    const sweep::SweepPoint point = sweep::tight_reference(points, defaults, case_atol);
    // One folder per reference setting: a changed grid never reuses another setting's reference.
    const std::filesystem::path directory = root / "reference" / point.name();
    reference_file = directory / results::kResultsFileName;
    reference_label = fmt::format("tight run {} ({})", point.name(), run_command_line(options, point));
    int ok = 1;
    if (lead) {
      const std::string status = sweep::read_run_status(reference_file);
      // A finished reference is reused (an inaccurate one is refused below without a rerun).
      if (!options.fresh && (status == results::layout::status::kOk || status == results::layout::status::kInaccurate)) {
        fmt::print(text, "reference: {}, reused from {}\n", reference_label, reference_file.string());
      } else {
        fmt::print(text, "reference: {} ...\n", reference_label);
        std::fflush(text);
        sweep::ChildOutcome outcome;
        sweep::PoolHooks hooks;
        hooks.on_finish = [&](std::size_t, const sweep::ChildOutcome& o) { outcome = o; };
        hooks.should_stop = [] { return StopSignals::received() != 0; };
        sweep::run_processes({child_job(options, executable, point, directory, true)}, 1, hooks);
        sweep::write_process_record(directory, outcome);
        fmt::print(text, "reference: {:.3f} s\n", outcome.wall_seconds);
        const std::string after = sweep::read_run_status(reference_file);
        ok = after == results::layout::status::kOk || after == results::layout::status::kInaccurate ? 1 : StopSignals::received() != 0 ? 2 : 0;
      }
      // A reference must pass its own accuracy check: errors against a wrong answer mean nothing.
      if (ok == 1 && sweep::read_run_status(reference_file) != results::layout::status::kOk) ok = 3;
    }
    ok = ranks.broadcast(ok);
    if (ok == 2) {
      if (lead) fmt::print(stderr, "limber: sweep interrupted during the reference run\n");
      return kExitInterrupted;
    }
    if (ok == 3) {
      throw NumericalError(fmt::format("the reference run {} finished, but its own accuracy check failed (status "
                                       "ok_inaccurate; its warnings are in {}), so errors against it mean nothing; "
                                       "give --reference RESULTS (a run you trust) or a grid whose richest setting "
                                       "runs accurately at a tighter step", point.name(),
                                       (directory / results::kRunLogFileName).string()));
    }
    if (ok == 0) {
      throw NumericalError(fmt::format("the reference run failed ({}); give --reference RESULTS or a grid "
                                       "whose finest point runs", (directory / results::kRunLogFileName).string()));
    }
  } else {
    reference_file = options.reference;
    const std::string status = sweep::read_run_status(reference_file);
    if (status != results::layout::status::kOk && status != results::layout::status::kInaccurate) {
      throw InputError(fmt::format("--reference: expected 'tight' or a finished results.h5 (status ok), got '{}'{}",
                                   options.reference,
                                   status.empty() ? " (no readable results file)" : " with status " + status));
    }
    reference_label = "the given file " + reference_file.string();
    if (lead) fmt::print(text, "reference: {}\n", reference_label);
    if (lead && status != results::layout::status::kOk) {
      fmt::print(stderr, "limber: warning: the reference's own accuracy check failed (status {}): errors against it "
                         "may mean little\n", status);
    }
  }
  const sweep::RunSeries reference = sweep::read_run_series(reference_file);
  const std::vector<std::string> quantities = options.quantities.empty()
                                                  ? sweep::default_quantities(reference)
                                                  : sweep::named_quantities(reference, options.quantities);

  // This rank's points: every size-th from its rank; finished ones are kept unless --fresh.
  std::vector<std::size_t> mine, resumed;
  std::vector<sweep::ChildJob> jobs;
  std::vector<std::size_t> job_point;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (static_cast<int>(k % static_cast<std::size_t>(ranks.size())) != ranks.rank()) continue;
    mine.push_back(k);
    const std::filesystem::path directory = root / results::kRunsFolder / points[k].name();
    if (!options.fresh && sweep::point_finished(directory)) {
      resumed.push_back(k);
      fmt::print(stderr, "[sweep] {}: finished in an earlier sweep, not rerun (--fresh reruns it)\n", points[k].name());
      continue;
    }
    jobs.push_back(child_job(options, executable, points[k], directory));
    job_point.push_back(k);
  }

  // The runs, with a progress line per finished point.
  const Clock::time_point start = Clock::now();
  int done = 0, failed = 0, running = 0;
  sweep::PoolHooks hooks;
  hooks.on_start = [&](std::size_t) { ++running; };
  hooks.on_finish = [&](std::size_t job, const sweep::ChildOutcome& outcome) {
    --running;
    ++done;
    const std::size_t k = job_point[job];
    const std::filesystem::path directory = root / results::kRunsFolder / points[k].name();
    sweep::write_process_record(directory, outcome);
    const bool ok = outcome.exit_code == kExitOk || outcome.exit_code == kExitInaccurate;
    failed += ok ? 0 : 1;
    fmt::print(stderr, "[sweep{}] {}/{} done, {} running, {} failed, {:.1f} s: {} {} in {:.2f} s\n",
               ranks.size() > 1 ? fmt::format(" rank {}", ranks.rank()) : "", done, jobs.size(), running, failed,
               std::chrono::duration<double>(Clock::now() - start).count(), points[k].name(),
               outcome.signal ? fmt::format("killed by signal {}", outcome.signal)
                              : fmt::format("exit {}", outcome.exit_code),
               outcome.wall_seconds);
  };
  hooks.should_stop = [] { return StopSignals::received() != 0; };
  sweep::run_processes(jobs, parallel, hooks);

  // Each rank measures its points; rank 0 gathers the rows (one JSON object a line).
  std::string my_rows;
  for (std::size_t k : mine) {
    sweep::SweepRow row = sweep::read_row(points[k], root / results::kRunsFolder / points[k].name(), reference, quantities);
    row.resumed = std::find(resumed.begin(), resumed.end(), k) != resumed.end();
    row.rank = ranks.rank();
    my_rows += sweep::row_json(row) + "\n";
  }
  const std::vector<std::string> gathered = ranks.gather_to_lead(my_rows);
  const int interrupted = ranks.max_over_ranks({StopSignals::received() != 0 ? 1 : 0}).front();
  if (!lead) return interrupted ? kExitInterrupted : kExitOk;

  // The rows in grid order; a point no rank reported stays "not_run".
  std::vector<sweep::SweepRow> rows(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    rows[k].point = points[k];
    rows[k].status = sweep::kNotRun;
  }
  for (const std::string& text : gathered) {
    std::size_t begin = 0;
    while (begin < text.size()) {
      const std::size_t end = text.find('\n', begin);
      const sweep::SweepRow row = sweep::row_from_json(text.substr(begin, end - begin));
      begin = end == std::string::npos ? text.size() : end + 1;
      for (std::size_t k = 0; k < points.size(); ++k) {
        if (points[k].name() == row.point.name()) rows[k] = row;
      }
    }
  }
  const std::optional<std::size_t> chosen =
      options.target ? sweep::cheapest_meeting(rows, *options.target, rms) : std::nullopt;
  fmt::print(text, "\nerrors against the reference ({}), largest over {} quantities (default: every joint reaction "
                   "and deflection component at least 1 % of the largest of its kind):",
             reference_label, quantities.size());
  print_table(text, rows, chosen);

  // Files for the user and the report; the reference's results make DIR a run directory.
  const std::filesystem::path folder = root / results::kSweepFolder;
  sweep::write_table_csv(folder / results::kWorkPrecisionFileName, rows, chosen);
  sweep::write_errors_csv(folder / results::kErrorsFileName, rows);
  const std::string json_rows = sweep::rows_json(rows, chosen);
  const std::string reference_json = fmt::format("{{\"label\": {}, \"results\": {}}}", json_string(reference_label),
                                                 json_string(reference_file.string()));
  std::string quantity_list = "[";
  for (std::size_t q = 0; q < quantities.size(); ++q) quantity_list += (q ? ", " : "") + json_string(quantities[q]);
  quantity_list += "]";
  const std::string document =
      fmt::format("{{\"status\": {}, \"case\": {}, \"reference\": {}, \"quantities\": {}, \"norm\": {}, \"target\": {}, "
                  "\"target_met\": {}, \"chosen\": {}, \"run_options\": {}, \"points\": {}, \"directory\": {}}}",
                  json_string(interrupted ? results::layout::status::kInterrupted : results::layout::status::kOk), json_string(options.case_file), reference_json,
                  quantity_list, json_string(options.norm),
                  options.target ? json_number(*options.target) : std::string("null"), chosen ? "true" : "false",
                  chosen ? json_string(rows[*chosen].point.name()) : std::string("null"),
                  chosen ? json_string(run_command_line(options, rows[*chosen].point)) : std::string("null"),
                  json_rows, json_string(root.string()));
  std::ofstream(folder / results::kWorkPrecisionJsonFileName, std::ios::binary) << document << '\n';
  if (std::filesystem::absolute(reference_file) != std::filesystem::absolute(root / results::kResultsFileName)) {
    std::filesystem::copy_file(reference_file, root / results::kResultsFileName,
                               std::filesystem::copy_options::overwrite_existing);
  }

  if (options.target) {
    if (chosen) {
      const sweep::SweepRow& row = rows[*chosen];
      fmt::print(text, "\ncheapest setting with {} error <= {:g} ({}): {} ({:.3f} s, {} error {}); run it with:\n  {}\n",
                 options.norm, *options.target, percent(*options.target), row.point.name(), row.wall_s, options.norm,
                 percent(row.error(rms)), run_command_line(options, row.point));
    } else {
      fmt::print(stderr, "limber: warning: no point meets the target {:g} ({} error) with its own accuracy check "
                         "passed; see the table\n", *options.target, options.norm);
    }
  }
  fmt::print(text, "wrote {}\n", folder.string());
  if (options.json) fmt::print(stdout, "{}\n", document);
  if (interrupted) {
    fmt::print(stderr, "limber: sweep interrupted; finished points are kept and a rerun resumes ({})\n",
               (root / results::kRunsFolder).string());
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
      "into DIR/reference/<point> and reused on resume.\n"
      "Exit codes: 0 done (failed points are rows), 1 bad input, 2 the reference run failed or\n"
      "its own accuracy check did not pass (status ok_inaccurate),\n"
      "3 internal error, 4 interrupted by SIGINT or SIGTERM (finished points kept; rerun resumes).");
  cli->add_option("case", options->case_file, "Case file (YAML, docs/case-format.md)")->required();
  cli->add_option("--over", options->over,
                  "Axes: names (integrator,rtol,step,modes: default values) or axis=v1,v2,... (several allowed)")
      ->required()
      ->expected(1, -1);
  cli->add_option("-o,--output", options->output_dir, "Output directory (default: out/<case file stem>_sweep)");
  cli->add_option("--reference", options->reference, "'tight' (one much tighter run) or a finished results.h5")
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
