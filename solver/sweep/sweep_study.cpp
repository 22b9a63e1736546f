#include "sweep/sweep_study.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <thread>

#include <fmt/format.h>

#include "cli/command.h"
#include "core/error.h"
#include "core/json_text.h"
#include "io/case_reader.h"
#include "results/directory_lock.h"
#include "results/file_names.h"
#include "results/results_layout.h"
#include "sweep/process_pool.h"
#include "sweep/run_series.h"
#include "sweep/sweep_grid.h"

namespace limber::sweep {

namespace {

using Clock = std::chrono::steady_clock;

void say(const std::function<void(const std::string&)>& to, const std::string& line) {
  if (to) to(line);
}

// The case's settings the grid's defaults come from.
CaseDefaults case_defaults(const io::Case& input) {
  CaseDefaults defaults;
  const integrate::IntegratorOptions& integrator = input.mechanism->run.integrator;
  defaults.method = integrator.method;
  defaults.rtol = integrator.rtol;
  defaults.step = integrator.step;
  for (const io::FlexibleBodyCase& body : input.flexible_bodies) {
    defaults.normal_modes = std::max(defaults.normal_modes, body.request.normal_count);
  }
  return defaults;
}

// The child `limber run` of a point (the reference runs without --max-wall: it must finish).
ChildJob child_job(const SweepRequest& request, const SweepPoint& point, const std::filesystem::path& directory,
                   bool reference = false) {
  std::vector<std::string> argv = {request.executable.string(), "run", request.case_file, "-o", directory.string(),
                                   "--json"};
  for (const std::string& option : point.run_options()) argv.push_back(option);
  if (request.t_end) argv.insert(argv.end(), {"--t-end", fmt::format("{}", *request.t_end)});
  if (request.atol && !point.atol) argv.insert(argv.end(), {"--atol", fmt::format("{}", *request.atol)});
  if (request.max_wall && !reference) {
    argv.insert(argv.end(), {"--max-wall", fmt::format("{}", *request.max_wall)});
  }
  return {argv, directory / results::kRunJsonFileName, directory / results::kRunLogFileName};
}

void check_request(const SweepRequest& request) {
  if (request.target && !(*request.target > 0.0)) {
    throw InputError(fmt::format("expected --target > 0 (a fraction, 0.01 = 1 %), got {:g}", *request.target));
  }
  if (request.jobs < 0) {
    throw InputError(fmt::format("expected --jobs >= 1 (0: the number of cores), got {}", request.jobs));
  }
  if (request.t_end && !(*request.t_end >= 0.0)) {
    throw InputError(fmt::format("expected --t-end >= 0, got {:g}", *request.t_end));
  }
}

bool finished_status(const std::string& status) {
  return status == results::layout::status::kOk || status == results::layout::status::kInaccurate;
}

// A reference run (`--reference tight` or `nonlinear`): run once (rank 0) into
// DIR/reference/<point> and reused on resume. `kind` names it in the label ("tight run ...").
// Returns false when interrupted during its run. Throws NumericalError when it failed.
bool make_reference_run(const SweepRequest& request, const RankGroup& ranks, const SweepHooks& hooks,
                        const SweepPoint& point, const char* kind, SweepOutcome& outcome) {
  // One folder per reference setting: a changed grid never reuses another setting's reference.
  const std::filesystem::path directory = request.root / "reference" / point.name();
  outcome.reference_file = directory / results::kResultsFileName;
  outcome.reference_label = fmt::format("{} run {} ({})", kind, point.name(), run_command_line(request, point));
  int ok = 1;
  if (ranks.rank() == 0) {
    // A finished reference is reused (an inaccurate one is refused below without a rerun).
    if (!request.fresh && finished_status(read_run_status(outcome.reference_file))) {
      say(hooks.text, fmt::format("reference: {}, reused from {}\n", outcome.reference_label,
                                  outcome.reference_file.string()));
    } else {
      say(hooks.text, fmt::format("reference: {} ...\n", outcome.reference_label));
      ChildOutcome child;
      PoolHooks pool;
      pool.on_finish = [&](std::size_t, const ChildOutcome& o) { child = o; };
      pool.should_stop = hooks.should_stop;
      run_processes({child_job(request, point, directory, true)}, 1, pool);
      write_process_record(directory, child);
      say(hooks.text, fmt::format("reference: {:.3f} s\n", child.wall_seconds));
      const bool stopped = hooks.should_stop && hooks.should_stop();
      ok = finished_status(read_run_status(outcome.reference_file)) ? 1 : stopped ? 2 : 0;
    }
    // A reference must pass its own accuracy check: errors against a wrong answer mean nothing.
    if (ok == 1 && read_run_status(outcome.reference_file) != results::layout::status::kOk) ok = 3;
  }
  ok = ranks.broadcast(ok);
  if (ok == 2) return false;
  const std::string log = (directory / results::kRunLogFileName).string();
  const std::string remedy = point.nonlinear ? "give --reference RESULTS (a run you trust) or a smaller step in "
                                               "the grid or the case"
                                             : "give --reference RESULTS (a run you trust) or a grid whose richest "
                                               "setting runs accurately at a tighter step";
  if (ok == 3) {
    throw NumericalError(fmt::format("the reference run {} finished, but its own accuracy check failed (status "
                                     "ok_inaccurate; its warnings are in {}), so errors against it mean nothing; {}",
                                     point.name(), log, remedy));
  }
  if (ok == 0) {
    throw NumericalError(fmt::format("the reference run failed ({}); {}", log,
                                     point.nonlinear ? "give --reference RESULTS or a smaller step"
                                                     : "give --reference RESULTS or a grid whose finest point runs"));
  }
  return true;
}

// A given reference file: it must be finished.
void given_reference(const SweepRequest& request, const RankGroup& ranks, const SweepHooks& hooks,
                     SweepOutcome& outcome) {
  outcome.reference_file = request.reference;
  const std::string status = read_run_status(outcome.reference_file);
  if (!finished_status(status)) {
    throw InputError(fmt::format("--reference: expected 'tight', 'nonlinear' or a finished results.h5 (status ok), got '{}'{}",
                                 request.reference,
                                 status.empty() ? " (no readable results file)" : " with status " + status));
  }
  outcome.reference_label = "the given file " + outcome.reference_file.string();
  if (ranks.rank() != 0) return;
  say(hooks.text, fmt::format("reference: {}\n", outcome.reference_label));
  if (status != results::layout::status::kOk) {
    say(hooks.log, fmt::format("limber: warning: the reference's own accuracy check failed (status {}): errors "
                               "against it may mean little\n", status));
  }
}

// This rank's points (every size-th from its rank), run; finished ones kept unless fresh.
// Returns the rows of this rank's points, one JSON object a line.
std::string run_my_points(const SweepRequest& request, const RankGroup& ranks, const SweepHooks& hooks,
                          const std::vector<SweepPoint>& points, const RunSeries& reference,
                          const std::vector<std::string>& quantities) {
  std::vector<std::size_t> mine, resumed;
  std::vector<ChildJob> jobs;
  std::vector<std::size_t> job_point;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (static_cast<int>(k % static_cast<std::size_t>(ranks.size())) != ranks.rank()) continue;
    mine.push_back(k);
    const std::filesystem::path directory = request.root / results::kRunsFolder / points[k].name();
    if (!request.fresh && point_finished(directory)) {
      resumed.push_back(k);
      say(hooks.log, fmt::format("[sweep] {}: finished in an earlier sweep, not rerun (--fresh reruns it)\n",
                                 points[k].name()));
      continue;
    }
    jobs.push_back(child_job(request, points[k], directory));
    job_point.push_back(k);
  }

  // The runs, with a progress line per finished point.
  const Clock::time_point start = Clock::now();
  int done = 0, failed = 0, running = 0;
  PoolHooks pool;
  pool.on_start = [&](std::size_t) { ++running; };
  pool.on_finish = [&](std::size_t job, const ChildOutcome& outcome) {
    --running;
    ++done;
    const std::size_t k = job_point[job];
    write_process_record(request.root / results::kRunsFolder / points[k].name(), outcome);
    const bool ok = outcome.exit_code == cli::kExitOk || outcome.exit_code == cli::kExitInaccurate;
    failed += ok ? 0 : 1;
    say(hooks.log, fmt::format("[sweep{}] {}/{} done, {} running, {} failed, {:.1f} s: {} {} in {:.2f} s\n",
                               ranks.size() > 1 ? fmt::format(" rank {}", ranks.rank()) : "", done, jobs.size(),
                               running, failed, std::chrono::duration<double>(Clock::now() - start).count(),
                               points[k].name(),
                               outcome.signal ? fmt::format("killed by signal {}", outcome.signal)
                                              : fmt::format("exit {}", outcome.exit_code),
                               outcome.wall_seconds));
  };
  pool.should_stop = hooks.should_stop;
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  run_processes(jobs, request.jobs > 0 ? request.jobs : cores, pool);

  std::string rows;
  for (std::size_t k : mine) {
    SweepRow row = read_row(points[k], request.root / results::kRunsFolder / points[k].name(), reference, quantities);
    row.resumed = std::find(resumed.begin(), resumed.end(), k) != resumed.end();
    row.rank = ranks.rank();
    rows += row_json(row) + "\n";
  }
  return rows;
}

// The rows in grid order from every rank's lines; a point no rank reported stays "not_run".
std::vector<SweepRow> gathered_rows(const std::vector<SweepPoint>& points, const std::vector<std::string>& gathered) {
  std::vector<SweepRow> rows(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    rows[k].point = points[k];
    rows[k].status = kNotRun;
  }
  for (const std::string& text : gathered) {
    std::size_t begin = 0;
    while (begin < text.size()) {
      const std::size_t end = text.find('\n', begin);
      const SweepRow row = row_from_json(text.substr(begin, end - begin));
      begin = end == std::string::npos ? text.size() : end + 1;
      for (std::size_t k = 0; k < points.size(); ++k) {
        if (points[k].name() == row.point.name()) rows[k] = row;
      }
    }
  }
  return rows;
}

std::string sweep_document(const SweepRequest& request, const SweepOutcome& outcome) {
  std::string quantity_list = "[";
  for (std::size_t q = 0; q < outcome.quantities.size(); ++q) {
    quantity_list += (q ? ", " : "") + json_string(outcome.quantities[q]);
  }
  quantity_list += "]";
  const std::optional<std::size_t> chosen = outcome.chosen;
  return fmt::format(
      "{{\"status\": {}, \"case\": {}, \"reference\": {{\"label\": {}, \"results\": {}}}, \"quantities\": {}, "
      "\"norm\": {}, \"target\": {}, \"target_met\": {}, \"chosen\": {}, \"run_options\": {}, \"points\": {}, "
      "\"directory\": {}}}",
      json_string(outcome.interrupted ? results::layout::status::kInterrupted : results::layout::status::kOk),
      json_string(request.case_file), json_string(outcome.reference_label),
      json_string(outcome.reference_file.string()), quantity_list, json_string(request.rms ? "rms" : "peak"),
      request.target ? json_number(*request.target) : std::string("null"), chosen ? "true" : "false",
      chosen ? json_string(outcome.rows[*chosen].point.name()) : std::string("null"),
      chosen ? json_string(run_command_line(request, outcome.rows[*chosen].point)) : std::string("null"),
      rows_json(outcome.rows, chosen), json_string(request.root.string()));
}

}  // namespace

std::string run_command_line(const SweepRequest& request, const SweepPoint& point) {
  std::string line = "limber run " + request.case_file;
  for (const std::string& option : point.run_options()) line += " " + option;
  if (request.t_end) line += fmt::format(" --t-end {:g}", *request.t_end);
  return line;
}

SweepOutcome run_sweep(const SweepRequest& request, const RankGroup& ranks, const SweepHooks& hooks) {
  check_request(request);
  const bool lead = ranks.rank() == 0;
  const io::Case input = io::read_case_file(request.case_file);
  if (!input.mechanism) {
    throw InputError("expected a mechanism (a 'bodies' section), got none", SourceLocation{request.case_file, 0, 0});
  }
  SweepOutcome outcome;
  outcome.lead = lead;
  const CaseDefaults defaults = case_defaults(input);
  outcome.points = expand_grid(parse_over(request.over, defaults), defaults);
  std::filesystem::create_directories(request.root);
  std::optional<results::DirectoryLock> lock;
  if (lead) lock.emplace(request.root);
  if (lead) {
    const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    say(hooks.text, fmt::format("limber sweep: {} ({}), {} points, {} at a time{}\n", input.title, input.file,
                                outcome.points.size(), request.jobs > 0 ? request.jobs : cores,
                                ranks.size() > 1 ? fmt::format(" on each of {} MPI ranks", ranks.size()) : ""));
  }

  // The reference: one tight or nonlinear run, made once and reused on resume, or a given file.
  if (request.reference == "tight" || request.reference == "nonlinear") {
    const double case_atol = request.atol.value_or(input.mechanism->run.integrator.atol);
    const bool nonlinear = request.reference == "nonlinear";
    const SweepPoint point = nonlinear ? nonlinear_reference(outcome.points, defaults)
                                       : tight_reference(outcome.points, defaults, case_atol);
    if (!make_reference_run(request, ranks, hooks, point, nonlinear ? "nonlinear" : "tight", outcome)) {
      outcome.interrupted = outcome.interrupted_in_reference = true;
      return outcome;
    }
  } else {
    given_reference(request, ranks, hooks, outcome);
  }
  const RunSeries reference = read_run_series(outcome.reference_file);
  outcome.quantities = request.quantities.empty() ? default_quantities(reference)
                                                  : named_quantities(reference, request.quantities);

  // Each rank runs and measures its points; rank 0 gathers the rows.
  const std::string my_rows = run_my_points(request, ranks, hooks, outcome.points, reference, outcome.quantities);
  const std::vector<std::string> gathered = ranks.gather_to_lead(my_rows);
  const bool stopped = hooks.should_stop && hooks.should_stop();
  outcome.interrupted = ranks.max_over_ranks({stopped ? 1 : 0}).front() != 0;
  if (!lead) return outcome;
  outcome.rows = gathered_rows(outcome.points, gathered);
  outcome.chosen = request.target ? cheapest_meeting(outcome.rows, *request.target, request.rms) : std::nullopt;

  // Files for the user and the report; the reference's results make DIR a run directory.
  const std::filesystem::path folder = request.root / results::kSweepFolder;
  write_table_csv(folder / results::kWorkPrecisionFileName, outcome.rows, outcome.chosen);
  write_errors_csv(folder / results::kErrorsFileName, outcome.rows);
  outcome.document = sweep_document(request, outcome);
  std::ofstream(folder / results::kWorkPrecisionJsonFileName, std::ios::binary) << outcome.document << '\n';
  const std::filesystem::path copy = request.root / results::kResultsFileName;
  if (std::filesystem::absolute(outcome.reference_file) != std::filesystem::absolute(copy)) {
    std::filesystem::copy_file(outcome.reference_file, copy, std::filesystem::copy_options::overwrite_existing);
  }
  return outcome;
}

}  // namespace limber::sweep
