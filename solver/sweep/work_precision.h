// The rows of `limber sweep`'s work-precision table (docs/sweep.md): for each grid point what
// its run cost (wall time, steps, rejected steps, Newton iterations, Jacobian and residual
// evaluations, peak memory), the run's own accuracy check, and its errors against the
// reference per compared quantity (select/series_error.h), max and rms.
//
// A point's row is rebuilt from its folder, DIR/runs/<point>/, alone:
//   results.h5    the run's results (written by the child `limber run`)
//   run.json      the child's --json report (stdout)
//   run.log       the child's text and warnings (stderr)
//   process.json  the sweep's record of the child: {"exit_code", "signal", "process_s",
//                 "peak_rss_kib", "spawn_error"}
// so a resumed sweep, and rank 0 of an MPI sweep, build the same table from the same files.
#pragma once

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "select/step_choice.h"
#include "sweep/process_pool.h"
#include "sweep/run_series.h"
#include "sweep/sweep_grid.h"

namespace limber::sweep {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct QuantityError {
  std::string quantity;
  double peak = kNaN;  // relative (fraction)
  double rms = kNaN;
};

// A point's status beyond a run's own (results/results_layout.h, layout::status): its process
// ended without a report (a signal, a crash), or no rank reported it.
inline constexpr const char* kCrashed = "crashed";
inline constexpr const char* kNotRun = "not_run";

struct SweepRow {
  SweepPoint point;
  std::string status;    // ok, ok_inaccurate, failed, crashed, interrupted, not_run
  std::string message;   // why it failed or crashed
  int exit_code = -1;    // of the child `limber run`; -1: killed by a signal or never started
  int signal = 0;
  bool resumed = false;  // finished in an earlier sweep, not rerun
  int rank = 0;          // MPI rank that ran it (0 without MPI)
  double wall_s = kNaN;      // the run's own wall time: assembly, integration, output [s]
  double process_s = kNaN;   // the whole child: reading, modal reduction, run [s]
  long steps = 0, rejected_steps = 0, newton_iterations = 0, jacobian_evaluations = 0, residual_evaluations = 0;
  double peak_rss_mib = kNaN;
  double energy_relative = kNaN, local_error = kNaN, drift_relative = kNaN;  // accuracy check
  std::vector<QuantityError> errors;  // finished runs only
  double error_peak = kNaN, error_rms = kNaN;  // largest over the quantities
  std::string worst_quantity;
  // Generalized-α points: steps per period of the highest retained frequency, 1 / (h f_max);
  // below select::kStepsPerPeriod the step does not resolve the modes (select/step_choice.h).
  double f_max_hz = kNaN;
  double steps_per_period = kNaN;
  bool resolved() const { return !(steps_per_period < select::kStepsPerPeriod); }

  // Finished (ok or ok_inaccurate): its errors mean something.
  bool finished() const;  // status ok or ok_inaccurate
  double error(bool rms) const { return rms ? error_rms : error_peak; }
};

// Writes DIR/runs/<point>/process.json for a child that ended (or could not start).
void write_process_record(const std::filesystem::path& point_directory, const ChildOutcome& outcome);

// True when the point's folder holds the sweep's process.json and a results.h5 with a final
// status, or the child refused the setting as bad input (exit 1): then the point is not rerun
// on resume. A crashed, killed or interrupted point runs again.
bool point_finished(const std::filesystem::path& point_directory);

// The row of `point` from its folder, with errors against `reference` over `quantities`.
// Never throws for a broken point: an unreadable file makes the row "crashed" with the reason.
SweepRow read_row(const SweepPoint& point, const std::filesystem::path& point_directory,
                  const RunSeries& reference, const std::vector<std::string>& quantities);

// The cheapest (shortest run wall time) row whose error (rms or peak) is at most `target` and
// whose own accuracy check passed (status ok; an ok_inaccurate point is never chosen). nullopt
// when none qualifies.
std::optional<std::size_t> cheapest_meeting(const std::vector<SweepRow>& rows, double target, bool rms);

// DIR/sweep/work_precision.csv: one row per point (header in docs/sweep.md).
void write_table_csv(const std::filesystem::path& file, const std::vector<SweepRow>& rows,
                     std::optional<std::size_t> chosen);
// DIR/sweep/errors.csv: point, quantity, error_peak, error_rms for every finished point.
void write_errors_csv(const std::filesystem::path& file, const std::vector<SweepRow>& rows);
// The rows as a JSON array (the same fields as the CSV, per-quantity errors as "errors").
std::string rows_json(const std::vector<SweepRow>& rows, std::optional<std::size_t> chosen);

// One row as a JSON object (rows_json's element) and back: how MPI ranks send their rows to
// rank 0. The point's atol (set only on a tight reference) does not travel.
std::string row_json(const SweepRow& row);
SweepRow row_from_json(const std::string& object);

}  // namespace limber::sweep
