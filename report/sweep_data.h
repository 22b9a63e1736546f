// What `limber sweep` left in a directory's `sweep/` folder, read from work_precision.csv (the
// table's columns are in docs/sweep.md; found by their header names, further ones ignored), for
// the report's "Work-precision sweep" section (docs/report.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace limber::report {

// One grid point of the sweep.
struct SweepPointRow {
  std::string point;       // e.g. "galpha_step0.0005_m5"
  std::string curve;       // its curve in the plot: "galpha, 5 modes"
  std::string status;      // ok, ok_inaccurate, failed, crashed, interrupted, not_run
  std::string message;
  std::optional<double> wall_s;       // the run's wall time [s]
  std::optional<double> peak_rss_mib; // the child process's peak memory [MiB]
  long long steps = 0, rejected_steps = 0, newton_iterations = 0, jacobian_evaluations = 0;
  std::optional<double> error_peak, error_rms;  // relative, against the reference
  std::string worst_quantity;
  std::string role;        // "chosen" or ""
};

struct SweepData {
  std::filesystem::path directory;  // DIR/sweep
  std::vector<SweepPointRow> points;
};

// Reads `run_directory`/sweep/work_precision.csv. nullopt when the folder does not exist; a
// missing or malformed file adds a note (naming the file and line) and leaves no points.
std::optional<SweepData> read_sweep(const std::filesystem::path& run_directory, std::vector<std::string>& notes);

}  // namespace limber::report
